// The C API's enums as the integers C callers pass. C lets any int through an
// enum parameter or field, and in C++ loading (or static_cast-ing to) an enum
// whose value lies outside its enumerators' range is undefined behaviour (UBSan's
// -fsanitize=enum reports it), so the implementation reads a caller's enum by its
// bytes and looks names up by integer.
#pragma once

#include <cstdint>
#include <cstring>
#include <type_traits>

template <typename E>
int enumValue(const E& e) {
  static_assert(std::is_enum<E>::value && sizeof(E) == sizeof(int), "a C API enum");
  int v;
  std::memcpy(&v, &e, sizeof v);
  return v;
}

// The name of each PrismAccel, PrismAa, PrismFilter, PrismFirstHit and
// PrismInsideTest value, or NULL for a value that is none of them.
const char* accelNameOf(std::int64_t value);
const char* aaNameOf(std::int64_t value);
const char* filterNameOf(std::int64_t value);
const char* firstHitNameOf(std::int64_t value);
const char* insideTestNameOf(std::int64_t value);
// PrismShadows value, or NULL for a value that is none of them.
const char* shadowsNameOf(std::int64_t value);
// PrismBounds value, or NULL for a value that is none of them.
const char* boundsNameOf(std::int64_t value);
// The channels of a PrismAov value; false for a value that is none.
bool aovChannelsOf(std::int64_t value, std::uint32_t* channels);
