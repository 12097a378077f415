#include "gpu/draw_list_wire.hpp"

#include <cstdint>
#include <cstring>
#include <stdexcept>
#include <type_traits>
#include <vector>

namespace twinraster::gpu {
namespace {

class Encoder {
 public:
  template <typename T>
  void Value(const T& value) {
    static_assert(std::is_trivially_copyable_v<T>);
    const char* p = reinterpret_cast<const char*>(&value);
    bytes.append(p, sizeof value);
  }
  template <typename T>
  void Vector(const std::vector<T>& values) {
    static_assert(std::is_trivially_copyable_v<T>);
    Value(std::uint64_t{values.size()});
    if (!values.empty()) bytes.append(reinterpret_cast<const char*>(values.data()), values.size() * sizeof(T));
  }
  std::string bytes;
};

class Decoder {
 public:
  explicit Decoder(std::string_view bytes) : bytes_(bytes) {}
  template <typename T>
  void Value(T& value) {
    std::memcpy(&value, Take(sizeof value), sizeof value);
  }
  template <typename T>
  void Vector(std::vector<T>& values) {
    std::uint64_t n = 0;
    Value(n);
    if (n > (bytes_.size() - at_) / sizeof(T))
      throw std::invalid_argument("draw list bytes: a vector runs past the end");
    values.resize(n);
    if (n > 0) std::memcpy(values.data(), Take(n * sizeof(T)), n * sizeof(T));  // an empty vector's data() may be null
  }
  bool Done() const { return at_ == bytes_.size(); }

 private:
  const char* Take(std::size_t n) {
    if (bytes_.size() - at_ < n) throw std::invalid_argument("draw list bytes: cut short");
    const char* p = bytes_.data() + at_;
    at_ += n;
    return p;
  }
  std::string_view bytes_;
  std::size_t at_ = 0;
};

// One walk over the list's fields, for both directions: what is written is what is read.
template <typename Coder, typename List>
void Walk(Coder& c, List& list) {
  c.Value(list.width), c.Value(list.height), c.Value(list.background);
  c.Value(list.reversed_z), c.Value(list.wireframe);
  std::uint64_t meshes = list.meshes.size();
  c.Value(meshes);
  if constexpr (!std::is_const_v<List>) list.meshes.resize(meshes);
  for (auto& mesh : list.meshes) {
    c.Vector(mesh.positions), c.Vector(mesh.triangles), c.Vector(mesh.colours);
    c.Value(mesh.shading), c.Vector(mesh.normals), c.Vector(mesh.vertex_colours);
  }
  c.Vector(list.draws);
  bool lit = list.lighting.has_value();
  c.Value(lit);
  if constexpr (!std::is_const_v<List>) {
    if (lit) list.lighting.emplace();
  }
  if (lit) {
    auto& lighting = *list.lighting;
    c.Value(lighting.ambient), c.Vector(lighting.lights), c.Vector(lighting.instances);
  }
}

}  // namespace

std::string EncodeDrawList(const DrawList& list) {
  Encoder e;
  Walk(e, list);
  return std::move(e.bytes);
}

DrawList DecodeDrawList(std::string_view bytes) {
  Decoder d(bytes);
  DrawList list;
  Walk(d, list);
  if (!d.Done()) throw std::invalid_argument("draw list bytes: more than one list");
  return list;
}

}  // namespace twinraster::gpu
