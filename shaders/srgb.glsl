// The sRGB transfer curve, as a PNG of `luz render` encodes it (SCENES.md "Image output",
// core/image.cpp srgb_encode): linear radiance in, display value in [0, 1] out; NaN and
// negatives give 0.
//
// L^(1/2.4) on [0.0031308, 1] is evaluated without pow(): with q = L^(1/4) (two square roots)
// it is q^(5/3), a smooth curve on q in [0.2365, 1] that this degree-5 polynomial follows within
// 8e-6, 0.002 of an 8-bit code (least squares on Chebyshev nodes). Mesa's software rasteriser
// computes pow() as exp2(y log2 x), two long polynomials per channel.
vec3 inverse_gamma(vec3 L) {
  vec3 q = sqrt(sqrt(L));
  return ((((-0.06197217 * q + 0.26632327) * q - 0.53780828) * q + 1.18462557) * q + 0.15497203) * q - 0.00614534;
}

vec3 srgb_encode(vec3 L) {
  vec3 c = clamp(L, 0.0, 1.0);
  vec3 curve = mix(1.055 * inverse_gamma(c) - 0.055, 12.92 * c, lessThanEqual(c, vec3(0.0031308)));
  return mix(vec3(0.0), curve, greaterThan(L, vec3(0.0)));  // NaN compares false: 0
}
