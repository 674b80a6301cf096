#include "raytracing/counters.h"

#include <fmt/format.h>

namespace luz::rt {

uint64_t Counters::total_rays() const {
  uint64_t n = 0;
  for (uint64_t r : rays) n += r;
  return n;
}

Counters& Counters::operator+=(const Counters& other) {
  for (size_t i = 0; i < rays.size(); ++i) rays[i] += other.rays[i];
  intersection_tests += other.intersection_tests;
  samples += other.samples;
  seconds += other.seconds;
  return *this;
}

std::string Counters::to_string() const {
  std::string s = fmt::format("rays: {} primary, {} shadow, {} reflected, {} transmitted ({} in all)\n",
                              (*this)[RayKind::primary], (*this)[RayKind::shadow],
                              (*this)[RayKind::reflected], (*this)[RayKind::transmitted],
                              total_rays());
  if (intersection_tests > 0)
    s += fmt::format("ray-triangle tests: {} ({:.1f} per ray)\n", intersection_tests,
                     double(intersection_tests) / double(std::max<uint64_t>(total_rays(), 1)));
  s += fmt::format("time: {:.3f} s, {:.2f} Mrays/s\n", seconds, rays_per_second() * 1e-6);
  return s;
}

}  // namespace luz::rt
