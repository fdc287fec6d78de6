// The RDAE tensor layout (passes/rdae/tensor.hpp): channel block b of pixel p at
// level size `size` sits in tile (b % tilesX, b / tilesX) of one texture.
#ifndef HUSH_RDAE_TENSOR_GLSL
#define HUSH_RDAE_TENSOR_GLSL

ivec2 rdaeTexel(ivec2 p, uint block, uint tilesX, ivec2 size) {
    return ivec2(int(block % tilesX), int(block / tilesX)) * size + p;
}

#endif
