// The sine, cosine and tangent, and the hypotenuse, that the chain, the scene and the pages use:
// the project's own, in plain IEEE double arithmetic (+ - * / sqrt, exact fmod and rounding to an
// integer), so that every build gives the same bits for the same argument (glibc's and musl's
// sin and cos differ in the last bit on some angles; docs/chain.md). It is not a C library: no
// long double, no float versions, and each function covers the arguments the project has.
#pragma once

namespace twinraster {

// Both at once, because a rotation needs both.
struct SineCosine {
  double sine = 0;
  double cosine = 1;
};

// sin and cos of an angle in degrees, faithfully rounded (error < 1 ulp; nearly always correctly
// rounded). The angle is reduced in degrees, exactly, so multiples of 90 give exact 0 and ±1 and
// sin 30° is exactly 0.5; an exact zero sine has the sign of `degrees`, an exact zero cosine is +0.
// Any finite angle (a scene's are at most 1e12 degrees); NaN or infinity gives NaN.
SineCosine SineCosineOfDegrees(double degrees);

// sin and cos of the double degrees·π/180, rounded as C and JavaScript round it, (degrees·π)/180:
// what the chapter's demos compute, Math.sin(degrees*Math.PI/180), for `--rules book`, which
// draws as they do. Faithfully rounded, nearly always correctly: the same bits as any C library
// (or browser) wherever that library is correctly rounded.
SineCosine SineCosineOfRoundedRadians(double degrees);

// tan of an angle in radians, |radians| < π/2 (a camera's half field of view), faithfully rounded.
double TangentOfRadians(double radians);

// sqrt(x² + y² + z²) without overflow or underflow in the squares; within 2 ulp, and the same
// bits in every build (std::hypot is a C library's own).
double Hypotenuse(double x, double y, double z = 0.0);

}  // namespace twinraster
