/**
 * @file   ofbExampleOptions.h
 * @brief  Command-line numbers of the example applications, checked
 *
 * A value that is not a number, has trailing characters or lies outside the
 * application's range is refused (the application prints its usage and exits), rather
 * than read as 0 the way atoi reads "abc".
 */
#ifndef ofbExampleOptions_h
#define ofbExampleOptions_h

#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <string>

namespace ofbexample
{
/// `text` as an integer in [low, high] into `value`; false (value unchanged) otherwise.
inline bool ParseInt(const std::string& text, long low, long high, int& value)
{
  char* end = nullptr;
  errno = 0;
  const long v = std::strtol(text.c_str(), &end, 10);
  const bool ok = !text.empty() && !*end && errno == 0 && v >= low && v <= high;
  value = ok ? static_cast<int>(v) : value;
  return ok;
}

/// `text` as a finite number in [low, high] into `value`; false (value unchanged) otherwise.
inline bool ParseDouble(const std::string& text, double low, double high, double& value)
{
  char* end = nullptr;
  const double v = std::strtod(text.c_str(), &end);
  const bool ok = !text.empty() && !*end && std::isfinite(v) && v >= low && v <= high;
  value = ok ? v : value;
  return ok;
}
}

#endif
