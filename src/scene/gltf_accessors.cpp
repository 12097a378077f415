#include "scene/gltf_accessors.hpp"

#include <cstring>

namespace twinraster {

namespace {

// Component k of element i, as a double (floats exactly; integers as their value).
double Component(const std::uint8_t* element, GltfComponent c, std::size_t k) {
  switch (c) {
    case GltfComponent::kFloat: {
      float f;
      std::memcpy(&f, element + 4 * k, 4);
      return f;
    }
    case GltfComponent::kUnsignedInt: {
      std::uint32_t u;
      std::memcpy(&u, element + 4 * k, 4);
      return u;
    }
    case GltfComponent::kUnsignedShort: {
      std::uint16_t u;
      std::memcpy(&u, element + 2 * k, 2);
      return u;
    }
    case GltfComponent::kShort: {
      std::int16_t s;
      std::memcpy(&s, element + 2 * k, 2);
      return s;
    }
    case GltfComponent::kUnsignedByte: return element[k];
    case GltfComponent::kByte: return static_cast<std::int8_t>(element[k]);
  }
  return 0;
}

// fn(i, element bytes) for each element, or fn(i, nullptr) for an accessor of zeros.
template <class Fn>
void ForEachElement(const GltfDocument& doc, const GltfAccessor& a, Fn&& fn) {
  const std::uint8_t* base = a.buffer ? doc.buffers[*a.buffer].data() + a.offset : nullptr;
  for (std::uint64_t i = 0; i < a.count; ++i) fn(static_cast<std::size_t>(i), base ? base + i * a.stride : nullptr);
}

}  // namespace

std::vector<glm::dvec3> ReadVec3s(const GltfDocument& doc, const GltfAccessor& a) {
  std::vector<glm::dvec3> out(static_cast<std::size_t>(a.count), glm::dvec3(0.0));
  ForEachElement(doc, a, [&](std::size_t i, const std::uint8_t* e) {
    if (e) out[i] = {Component(e, a.component, 0), Component(e, a.component, 1), Component(e, a.component, 2)};
  });
  return out;
}

std::vector<glm::dvec4> ReadColours(const GltfDocument& doc, const GltfAccessor& a) {
  const double max = a.component == GltfComponent::kUnsignedByte    ? 255.0
                     : a.component == GltfComponent::kUnsignedShort ? 65535.0
                                                                    : 1.0;
  std::vector<glm::dvec4> out(static_cast<std::size_t>(a.count), glm::dvec4(0, 0, 0, 1));
  ForEachElement(doc, a, [&](std::size_t i, const std::uint8_t* e) {
    if (!e) return;
    for (std::uint32_t k = 0; k < a.components && k < 4; ++k) {
      out[i][static_cast<glm::length_t>(k)] = Component(e, a.component, k) / max;
    }
  });
  return out;
}

std::vector<std::uint32_t> ReadIndices(const GltfDocument& doc, const GltfAccessor& a) {
  std::vector<std::uint32_t> out(static_cast<std::size_t>(a.count), 0);
  ForEachElement(doc, a, [&](std::size_t i, const std::uint8_t* e) {
    if (e) out[i] = static_cast<std::uint32_t>(Component(e, a.component, 0));
  });
  return out;
}

}  // namespace twinraster
