#include "page_module/module_runtime.hpp"

#include "base/usage_error.hpp"
#include "scene/scene_error.hpp"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <exception>
#include <stdexcept>
#include <string>
#include <typeinfo>

namespace twinraster::page_module {

namespace {

char g_message[kMessageCapacity];
std::uint32_t g_message_size = 0;

// The exception types the module's code throws: the project's two errors, the standard ones its
// stages throw (std::invalid_argument, std::logic_error, std::runtime_error) and nlohmann's JSON
// errors. Each derives from std::exception alone, one class after another, so the object thrown
// starts with its std::exception and its what() can be read; any other type is only named.
bool IsKnownException(const std::type_info& type) {
  static const std::type_info* const known[] = {&typeid(SceneError),
                                                &typeid(UsageError),
                                                &typeid(std::runtime_error),
                                                &typeid(std::logic_error),
                                                &typeid(std::invalid_argument),
                                                &typeid(std::out_of_range),
                                                &typeid(std::length_error),
                                                &typeid(std::bad_alloc),
                                                &typeid(nlohmann::json::parse_error),
                                                &typeid(nlohmann::json::type_error),
                                                &typeid(nlohmann::json::out_of_range),
                                                &typeid(nlohmann::json::invalid_iterator),
                                                &typeid(nlohmann::json::other_error)};
  return std::any_of(std::begin(known), std::end(known), [&](const std::type_info* k) { return *k == type; });
}

}  // namespace

const char* MessageText() { return g_message; }
std::uint32_t MessageSize() { return g_message_size; }

void SetMessage(std::string_view text) {
  g_message_size = static_cast<std::uint32_t>(std::min<std::size_t>(text.size(), kMessageCapacity));
  std::memcpy(g_message, text.data(), g_message_size);
}

}  // namespace twinraster::page_module

// What the compiler calls for `throw` (the Itanium C++ ABI, which wasm32 follows): memory for the
// exception object, then the throw itself. Nothing unwinds, so the object is never freed; the page
// drops the whole instance after the trap.
extern "C" void* __cxa_allocate_exception(std::size_t bytes) noexcept {
  void* object = std::malloc(bytes);
  if (object == nullptr) __builtin_trap();
  return object;
}

extern "C" [[noreturn]] void __cxa_throw(void* object, std::type_info* type, void (*)(void*)) {
  using twinraster::page_module::SetMessage;
  if (type != nullptr && twinraster::page_module::IsKnownException(*type)) {
    SetMessage(static_cast<const std::exception*>(object)->what());
  } else {
    SetMessage(std::string("an exception of type ") + (type != nullptr ? type->name() : "?") + " (no message)");
  }
  __builtin_trap();
}

// Registers a thread_local object's destructor for when its thread exits. The module's one thread
// never exits (the page drops the whole instance), so there is nothing to register.
extern "C" int __cxa_thread_atexit(void (*)(void*), void*, void*) noexcept { return 0; }

// fmaf, replacing wasi-libc's: musl's fmaf finds the one inexact case of its double sum (exactly
// halfway between two floats) and redoes the sum rounding toward zero, but WebAssembly has only
// rounding to nearest, so there it always rounds that case away from zero (fmaf_check.hpp's
// proof found it wrong on 46,221 of 1,430,880 triples). This one rounds the exact product's sum
// to odd in double: if the sum is inexact and its last bit even, it steps one double toward the
// exact value, whose error TwoSum gives exactly. A double rounded to odd, with 53 bits for the
// float's 24, then rounds to the float nearest the exact value (docs/building.md).
extern "C" float fmaf(float a, float b, float c) {
  const double product = static_cast<double>(a) * b;  // exact: 24 + 24 bits fit in 53
  const double sum = product + c;
  if (!std::isfinite(sum)) return static_cast<float>(sum);
  const double c_part = sum - product;
  const double error = (product - (sum - c_part)) + (c - c_part);
  std::uint64_t bits = std::bit_cast<std::uint64_t>(sum);
  if (error != 0 && (bits & 1) == 0) bits = (error > 0) == (sum > 0) ? bits + 1 : bits - 1;
  return static_cast<float>(std::bit_cast<double>(bits));
}
