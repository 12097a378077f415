// twinraster in one include for other projects: load a scene (or an OBJ file, framed), build its
// draw list, render it on the CPU twin, write a PNG (what twinraster::twinraster links). The GPU
// renderer is "gpu/gpu_renderer.hpp", with twinraster::gpu.
#pragma once

#include "chain/draw_list.hpp"
#include "cpu/cpu_renderer.hpp"
#include "files/png_file.hpp"
#include "scene/obj_scene.hpp"
#include "scene/scene_loader.hpp"
