#pragma once
// Tile lists: how a kernel with a rare, costly case pays for it only where it occurs.
// Lavapipe runs every branch of a shader under a lane mask, so a branch that no pixel
// takes costs as much as one every pixel takes (docs/benchmarks.md, "Rare cases in
// listed tiles"); a GPU pays the same wherever one lane of a warp takes it. Such a
// kernel is split in two dispatches of one shader (shaders/common/tile_list.glsl):
//   "<node>"          the classifying variant, over every tile (one workgroup each):
//                     the common case, and the tile listed where a pixel needs more;
//   "<node>.<case>"   the listed variant, an indirect dispatch of one workgroup per
//                     listed tile: the whole kernel, overwriting those tiles.
// Their output is the one-dispatch kernel's, bit for bit (each pixel runs the same
// code in one of the two). The list, reset each frame by addTileListPass, is a
// buffer of 4 + 2 n uint32 for an image of n tiles.
#include <string>

#include <hush/passes/node_context.hpp>

namespace hush::passes {

// uint32 count of a tile list for an image of `size` in tiles of `tile` pixels.
uint64_t tileListWords(rhi::Extent2D size, rhi::Extent2D tile);

// Adds pass "<name>": an empty list of the output's tiles of `tile` pixels, to be
// taken readWrite("tiles") by the classifying pass, then readIndirect("tiles") by the
// listed pass. Its size follows the output size.
graph::BufferHandle addTileListPass(NodeContext& ctx, const std::string& name, rhi::Extent2D tile);

} // namespace hush::passes
