// The input of a fuzz target as a file, for parsers that read a path: one file per
// process under $TMPDIR (or /tmp), rewritten for every input.
#ifndef ofbFuzzFile_h
#define ofbFuzzFile_h

#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <string>

#include <unistd.h>

/// Write `data` to this process's file named after `stem` and `suffix`; its path.
inline const std::string& ofbFuzzWriteInput(const char* stem,
  const char* suffix,
  const uint8_t* data,
  size_t size)
{
  static const std::string path = [stem, suffix]
  {
    const char* dir = std::getenv("TMPDIR");
    return std::string(dir && *dir ? dir : "/tmp") + "/" + stem + "-" + std::to_string(getpid()) +
      suffix;
  }();
  std::FILE* file = std::fopen(path.c_str(), "wb");
  if (!file)
  {
    std::perror(path.c_str());
    std::abort();
  }
  if (size > 0)
  {
    std::fwrite(data, 1, size, file);
  }
  std::fclose(file);
  return path;
}

#endif
