// Which lavapipe the CPU twin copies: the few operations whose arithmetic differs between Mesa
// releases and between the CPU paths Mesa's JIT takes (docs/lavapipe-paths.md says which, with
// Mesa's file and line). The defaults are Mesa 22.3.6 on an x86-64 CPU with AVX2 and FMA.
#pragma once

namespace twinraster::cpu {

struct RasterRules {
  // The JIT fuses a * b + c into one rounding (LLVM's fmuladd on a CPU with FMA): the viewport
  // transform of shader vertices and the per-pixel depth plane. Without FMA: a multiply, then an
  // add, each rounded.
  bool fused_multiply_add = true;
  // lavapipe's native vector width in bits (LP_NATIVE_VECTOR_WIDTH; 256 with AVX, else 128).
  int vector_bits = 256;
};

}  // namespace twinraster::cpu
