// A deterministic mutation driver for the fuzz targets of Testing/Fuzz, for compilers
// without libFuzzer (GCC) and for reproducible runs. It calls the target's
// LLVMFuzzerTestOneInput, as libFuzzer would, on every seed, then on mutations of the
// seeds (bit flips, interesting values, erased, inserted and duplicated bytes, splices of
// two seeds) drawn from a fixed pseudo-random sequence, until a number of executions or
// a time limit is reached. A crash, a sanitizer report or a failed check of the target
// ends the program like with libFuzzer; the input that caused it is saved first.
//
//   ofbFuzzX [-runs=N (-1: no limit)] [-max_total_time=S] [-seed=K] [-artifact_prefix=P] PATH...
//
// PATH: seed files or directories of seeds (read, never written). The options have
// libFuzzer's names so that one command line serves both.
#include <algorithm>
#include <chrono>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <iostream>
#include <iterator>
#include <random>
#include <string>
#include <vector>

#include <dirent.h>
#include <sys/stat.h>

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size);

namespace
{
using Bytes = std::vector<uint8_t>;

/// The bytes of `path`, or false.
bool ReadFile(const std::string& path, Bytes& bytes)
{
  std::ifstream in(path, std::ios::binary);
  if (!in)
  {
    return false;
  }
  bytes.assign(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
  return true;
}

/// Add the files of `path` (a file, or a directory of files, sorted by name) to `seeds`.
void AddSeeds(const std::string& path, std::vector<Bytes>& seeds)
{
  struct stat info;
  if (stat(path.c_str(), &info) != 0)
  {
    std::cerr << "ofbFuzzDriver: cannot read " << path << "\n";
    std::exit(2);
  }
  std::vector<std::string> files;
  if (S_ISDIR(info.st_mode))
  {
    if (DIR* dir = opendir(path.c_str()))
    {
      while (dirent* entry = readdir(dir))
      {
        const std::string file = path + "/" + entry->d_name;
        if (entry->d_name[0] != '.' && stat(file.c_str(), &info) == 0 && S_ISREG(info.st_mode))
        {
          files.push_back(file);
        }
      }
      closedir(dir);
    }
    std::sort(files.begin(), files.end());
  }
  else
  {
    files.push_back(path);
  }
  for (const std::string& file : files)
  {
    Bytes bytes;
    if (ReadFile(file, bytes))
    {
      seeds.push_back(bytes);
    }
  }
}

/// A mutation of `seeds[k]`: one to four random edits, as libFuzzer's basic mutators.
Bytes Mutate(const std::vector<Bytes>& seeds, std::mt19937_64& random)
{
  auto below = [&random](size_t n) { return n == 0 ? size_t(0) : size_t(random() % n); };
  Bytes b = seeds[below(seeds.size())];
  static const uint64_t interesting[] = { 0,
    1,
    0x7F,
    0x80,
    0xFF,
    0x7FFF,
    0xFFFF,
    0x7FFFFFFF,
    0x80000000,
    0xFFFFFFFF,
    0x7FF0000000000000ull,
    0x7FF8000000000000ull,
    0xFFFFFFFFFFFFFFFFull,
    0x4B189680 /* 1e7f */,
    0x7F7FFFFF /* FLT_MAX */,
    0x7FEFFFFFFFFFFFFFull /* DBL_MAX */ };
  const int edits = 1 + static_cast<int>(below(4));
  for (int e = 0; e < edits; ++e)
  {
    switch (below(7))
    {
      case 0: // flip a bit
        if (!b.empty())
        {
          b[below(b.size())] ^= static_cast<uint8_t>(1u << below(8));
        }
        break;
      case 1: // a random byte
        if (!b.empty())
        {
          b[below(b.size())] = static_cast<uint8_t>(random());
        }
        break;
      case 2: // an interesting value of 1, 2, 4 or 8 bytes, little-endian
      {
        const size_t width = size_t(1) << below(4);
        if (b.size() >= width)
        {
          const size_t at = below(b.size() - width + 1);
          const uint64_t v = interesting[below(sizeof(interesting) / sizeof(interesting[0]))];
          for (size_t i = 0; i < width; ++i)
          {
            b[at + i] = static_cast<uint8_t>(v >> (8 * i));
          }
        }
        break;
      }
      case 3: // erase a run
        if (!b.empty())
        {
          const size_t at = below(b.size());
          b.erase(b.begin() + at, b.begin() + at + 1 + below(std::min<size_t>(64, b.size() - at)));
        }
        break;
      case 4: // insert random bytes
      {
        const size_t at = below(b.size() + 1);
        Bytes extra(1 + below(16));
        for (uint8_t& x : extra)
        {
          x = static_cast<uint8_t>(random());
        }
        b.insert(b.begin() + at, extra.begin(), extra.end());
        break;
      }
      case 5: // duplicate a run
        if (!b.empty() && b.size() < (1u << 20))
        {
          const size_t at = below(b.size());
          const size_t n = 1 + below(std::min<size_t>(256, b.size() - at));
          const Bytes run(b.begin() + at, b.begin() + at + n);
          b.insert(b.begin() + below(b.size() + 1), run.begin(), run.end());
        }
        break;
      default: // splice: this seed's head, another's tail
      {
        const Bytes& other = seeds[below(seeds.size())];
        const size_t head = below(b.size() + 1);
        const size_t tail = below(other.size() + 1);
        b.resize(head);
        b.insert(b.end(), other.begin() + tail, other.end());
        break;
      }
    }
  }
  return b;
}

/// Save the input being run, so that a crash leaves it behind (libFuzzer's crash-*).
void SaveCurrent(const std::string& path, const Bytes& input)
{
  std::ofstream out(path, std::ios::binary | std::ios::trunc);
  out.write(
    reinterpret_cast<const char*>(input.data()), static_cast<std::streamsize>(input.size()));
}
}

int main(int argc, char* argv[])
{
  long long runs = 1000;
  double seconds = 60.0;
  unsigned long long seed = 1;
  std::string prefix = "./";
  std::vector<Bytes> seeds;
  for (int i = 1; i < argc; ++i)
  {
    const std::string arg = argv[i];
    if (arg.rfind("-runs=", 0) == 0)
    {
      runs = std::atoll(arg.c_str() + 6);
    }
    else if (arg.rfind("-max_total_time=", 0) == 0)
    {
      seconds = std::atof(arg.c_str() + 16);
    }
    else if (arg.rfind("-seed=", 0) == 0)
    {
      seed = std::strtoull(arg.c_str() + 6, nullptr, 10);
    }
    else if (arg.rfind("-artifact_prefix=", 0) == 0)
    {
      prefix = arg.substr(17);
    }
    else if (!arg.empty() && arg[0] == '-')
    {
      // Other libFuzzer options (-timeout=, -rss_limit_mb=, ...) have no effect here.
    }
    else
    {
      AddSeeds(arg, seeds);
    }
  }
  if (seeds.empty())
  {
    seeds.emplace_back();
  }
  const std::string current = prefix + "current-input";
  const auto start = std::chrono::steady_clock::now();
  auto elapsed = [&start]()
  { return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count(); };
  long long done = 0;
  for (const Bytes& s : seeds)
  {
    SaveCurrent(current, s);
    LLVMFuzzerTestOneInput(s.data(), s.size());
    ++done;
  }
  std::mt19937_64 random(seed);
  while ((runs < 0 || done < runs) && elapsed() < seconds)
  {
    const Bytes input = Mutate(seeds, random);
    SaveCurrent(current, input);
    LLVMFuzzerTestOneInput(input.data(), input.size());
    ++done;
  }
  std::remove(current.c_str());
  std::cout << "ofbFuzzDriver: " << done << " executions (" << seeds.size() << " seeds) in "
            << elapsed() << " s, seed " << seed << ", no crash\n";
  return 0;
}
