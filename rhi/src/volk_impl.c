/* volk's implementation, compiled once into hush::rhi from Debian's libvulkan-volk-dev. */
#include <volk.c>
