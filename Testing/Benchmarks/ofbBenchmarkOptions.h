// Command-line values shared by the benchmark programs.
#ifndef ofbBenchmarkOptions_h
#define ofbBenchmarkOptions_h

#include <cstdlib>
#include <sstream>
#include <string>
#include <vector>

namespace ofbbench
{
/// The comma-separated integers of `text` ("512,1024,2048"), each as atoi reads it.
inline std::vector<int> ParseIntList(const std::string& text)
{
  std::vector<int> values;
  std::stringstream list(text);
  std::string item;
  while (std::getline(list, item, ','))
  {
    values.push_back(std::atoi(item.c_str()));
  }
  return values;
}
}

#endif
