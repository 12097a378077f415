// The names a Vulkan device is asked by (--device): the common name the manual uses for its family
// (lavapipe, swiftshader), or any part of its full name, ignoring case. It reads no device and
// chooses none: gpu/ chooses among the devices present, cpu/ the twin's rules when none is opened.
#pragma once

#include <algorithm>
#include <array>
#include <string>
#include <string_view>

namespace twinraster {

// A family of devices the manual names: its common name, and how each of its full names begins.
struct DeviceFamily {
  std::string_view common_name;  // "lavapipe"
  std::string_view name_start;   // "llvmpipe", as in "llvmpipe (LLVM 15.0.6, 256 bits)"
};

// Listed in the order of preference when a name asks for devices of several families.
inline constexpr std::array kDeviceFamilies = {
    DeviceFamily{"lavapipe", "llvmpipe"},
    DeviceFamily{"swiftshader", "SwiftShader"},
};
inline constexpr const DeviceFamily& kLavapipeFamily = kDeviceFamilies[0];
inline constexpr const DeviceFamily& kSwiftShaderFamily = kDeviceFamilies[1];

inline char LowerAscii(char c) { return c >= 'A' && c <= 'Z' ? static_cast<char>(c - 'A' + 'a') : c; }

inline bool EqualsIgnoringCase(std::string_view a, std::string_view b) {
  return std::equal(a.begin(), a.end(), b.begin(), b.end(),
                    [](char x, char y) { return LowerAscii(x) == LowerAscii(y); });
}

inline bool ContainsIgnoringCase(std::string_view haystack, std::string_view needle) {
  return std::search(haystack.begin(), haystack.end(), needle.begin(), needle.end(),
                     [](char x, char y) { return LowerAscii(x) == LowerAscii(y); }) != haystack.end();
}

inline bool StartsIgnoringCase(std::string_view text, std::string_view start) {
  return text.size() >= start.size() && EqualsIgnoringCase(text.substr(0, start.size()), start);
}

// The family of a device by its full name, or null for a device the manual has no name for.
inline const DeviceFamily* FamilyOfDevice(std::string_view device_name) {
  for (const DeviceFamily& family : kDeviceFamilies) {
    if (StartsIgnoringCase(device_name, family.name_start)) return &family;
  }
  return nullptr;
}

// Whether --device `asked` asks for the device named `device_name`.
inline bool AsksForDevice(std::string_view asked, std::string_view device_name) {
  const DeviceFamily* family = FamilyOfDevice(device_name);
  return ContainsIgnoringCase(device_name, asked) || (family && EqualsIgnoringCase(asked, family->common_name));
}

// Whether `asked` may name a device of `family` before any device is seen: its common name, a part
// of how its names begin, or a name that begins so.
inline bool MayAskForFamily(std::string_view asked, const DeviceFamily& family) {
  return EqualsIgnoringCase(asked, family.common_name) || ContainsIgnoringCase(family.name_start, asked) ||
         StartsIgnoringCase(asked, family.name_start);
}

// "lavapipe (llvmpipe (LLVM 15.0.6, 256 bits))": a device as it is listed to be asked for; the full
// name alone when its family has no common name.
inline std::string AskableName(std::string_view device_name) {
  const DeviceFamily* family = FamilyOfDevice(device_name);
  if (!family) return std::string(device_name);
  return std::string(family->common_name) + " (" + std::string(device_name) + ")";
}

// What a backend's name typed as a device's means ("gpu is a backend, not a device: ..."); empty
// for any other name. A real device may still contain it ("Virtio-GPU"), so only say it when
// nothing matched.
inline std::string BackendNotDevice(std::string_view asked) {
  std::string_view meaning;
  if (EqualsIgnoringCase(asked, "gpu")) meaning = "--backend gpu draws on Vulkan alone (on lavapipe by default)";
  if (EqualsIgnoringCase(asked, "cpu")) meaning = "--backend cpu draws on the CPU twin alone, with no device";
  if (EqualsIgnoringCase(asked, "both")) meaning = "--backend both (the default) draws on Vulkan and the twin";
  if (meaning.empty()) return "";
  std::string text(asked);
  text.append(" is a backend, not a device: ").append(meaning);
  return text;
}

}  // namespace twinraster
