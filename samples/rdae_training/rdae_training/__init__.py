"""Training toolkit for hush's recurrent denoising autoencoder (Chaitanya et al. 2017).

The C++ inference (passes/rdae) and this package describe one network; the weights
file (safetensors) is the contract between them: docs/passes/rdae.md.
"""
