#include "scene/lighting_reader.hpp"

#include <glm/geometric.hpp>

#include <sstream>

namespace twinraster {

namespace {

// Light adds to a surface's brightness; a negative term would darken it below its own colour.
double ReadNonNegative(const JsonReader& r) {
  const double x = r.Number();
  if (x < 0) {
    std::ostringstream s;
    s << "must be 0 or more, found " << x;
    r.Fail(s.str());
  }
  return x;
}

Light ReadLight(const JsonReader& r) {
  r.ExpectObject();
  const JsonReader type = r.Required("type");
  const std::string kind = type.String();
  Light light;
  if (kind == "directional") {
    r.ExpectObject({"type", "direction", "intensity"});
    light.kind = Light::Kind::kDirectional;
    const JsonReader direction = r.Required("direction");
    light.vector = direction.Vec3();
    // l is divided by its length; shorter than a scene's smallest size, that length is noise.
    const double length = glm::length(light.vector);
    if (length == 0) direction.Fail("a directional light's direction must not be the zero vector");
    if (length < kMinPositive) {
      std::ostringstream s;
      s << "a directional light's direction is absurdly short (length " << length << ", below " << kMinPositive << ")";
      direction.Fail(s.str());
    }
  } else if (kind == "point") {
    r.ExpectObject({"type", "position", "intensity"});
    light.kind = Light::Kind::kPoint;
    light.vector = r.Required("position").Vec3();
  } else {
    const std::string suggestion = ClosestMatch(kind, {"directional", "point"});
    type.Fail("expected \"directional\" or \"point\", found \"" + kind + "\"" +
              (suggestion.empty() ? "" : " (did you mean \"" + suggestion + "\"?)"));
  }
  light.intensity = ReadNonNegative(r.Required("intensity"));
  return light;
}

}  // namespace

Lighting ReadLighting(const JsonReader& r) {
  r.ExpectObject({"ambient", "lights"});
  Lighting lighting;
  if (auto ambient = r.Find("ambient")) lighting.ambient = ReadNonNegative(*ambient);
  r.Required("lights").ForEachElement([&](const JsonReader& light) { lighting.lights.push_back(ReadLight(light)); });
  return lighting;
}

}  // namespace twinraster
