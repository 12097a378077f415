// A DrawList as bytes and back, for sending it to the GPU process (gpu/isolated_gpu.hpp): both
// ends are the same executable, so every vector's elements go as they lie in memory.
#pragma once

#include "chain/draw_list.hpp"

#include <string>
#include <string_view>

namespace twinraster::gpu {

std::string EncodeDrawList(const DrawList& list);
// Throws std::invalid_argument when the bytes are not a whole list.
DrawList DecodeDrawList(std::string_view bytes);

}  // namespace twinraster::gpu
