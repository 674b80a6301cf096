#include "raytracing/counters.h"

#include <fmt/format.h>

#include "core/i18n.h"

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
  using i18n::trf;
  std::string s = trf("rays: {} primary, {} shadow, {} reflected, {} transmitted ({} in all)",
                      (*this)[RayKind::primary], (*this)[RayKind::shadow], (*this)[RayKind::reflected],
                      (*this)[RayKind::transmitted], total_rays()) + "\n";
  if (intersection_tests > 0)
    s += trf("ray-triangle tests: {} ({:.1f} per ray)", intersection_tests,
             double(intersection_tests) / double(std::max<uint64_t>(total_rays(), 1))) + "\n";
  s += trf("time: {:.3f} s, {:.2f} Mrays/s", seconds, rays_per_second() * 1e-6) + "\n";
  return s;
}

}  // namespace luz::rt
