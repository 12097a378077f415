// Proof that lavapipe drew on the CPU path this run names (GALLIUM_OVERRIDE_CPU_CAPS and
// LP_NATIVE_VECTOR_WIDTH, or this CPU's own), from what lavapipe itself shows: the vector width in
// its device name, and the arithmetic in its pictures. The expected path comes from the variables
// and the kernel's /proc/cpuinfo, not from the twin's own CPUID reading, so a path the driver
// ignored, or a twin that misread it, fails here. It does not check the twin's other rules
// (rules_test.cpp does).
#pragma once

namespace twinraster::test {

// Fails the current test unless SharedGpu()'s lavapipe names the vector width of the path this
// run names, and draws two filled scenes with that path's arithmetic: equal, pixel for pixel, to
// the twin with fused multiply-adds on an FMA path and with separate roundings on the sse4.1 path,
// and different from the other one; on the nosse path (x87), different from both.
void RequireLavapipeOnNamedPath();

}  // namespace twinraster::test
