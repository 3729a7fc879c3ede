// The names of the temporaries that vtkOFBWriter and vtkOFBStagedFiles write beside a
// target before renaming them into place, and which of them a process that died left:
// "<name>.tmp-<host>-<pid>-<n>", the host being the machine's name with every character
// but letters, digits, '_' and '.' made '_'. A later write removes the temporaries of
// processes of its own machine that no longer run; a temporary of another machine (a
// folder shared by several machines, as an MPI job's) is kept, as its process cannot be
// asked from here. Names without a host ("<name>.tmp-<pid>-<n>") are taken as this
// machine's. POSIX only.
#ifndef vtkOFBTemporaryNames_h
#define vtkOFBTemporaryNames_h

#include <cerrno>
#include <cstdlib>
#include <signal.h>
#include <string>
#include <unistd.h>

namespace vtkofbtemporary
{
/// This machine's name as a temporary's name carries it (never empty, no '-').
inline std::string Host()
{
  char name[256] = { 0 };
  std::string host = gethostname(name, sizeof(name) - 1) == 0 ? name : "";
  for (char& c : host)
  {
    const bool kept = (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') ||
      c == '_' || c == '.';
    c = kept ? c : '_';
  }
  return host.empty() ? std::string("localhost") : host;
}

/// What follows ".tmp-" in the name of this process's temporary number `n`.
inline std::string Tag(unsigned long n)
{
  return Host() + "-" + std::to_string(static_cast<long>(getpid())) + "-" + std::to_string(n);
}

/// Whether `text` is a decimal number, its value in `value`.
inline bool ParseNumber(const std::string& text, long& value)
{
  if (text.empty() || text.find_first_not_of("0123456789") != std::string::npos || text.size() > 18)
  {
    return false;
  }
  value = std::strtol(text.c_str(), nullptr, 10);
  return true;
}

/**
 * Whether `tag` (what follows ".tmp-" in a name: "<host>-<pid>-<n>", or "<pid>-<n>")
 * names a temporary of a process of this machine that no longer runs (not this process).
 * False for any other text.
 */
inline bool IsStale(const std::string& tag)
{
  const std::string::size_type last = tag.rfind('-');
  if (last == std::string::npos || last == 0)
  {
    return false;
  }
  const std::string::size_type before = tag.rfind('-', last - 1);
  const std::string host = before == std::string::npos ? Host() : tag.substr(0, before);
  const std::string pidText =
    before == std::string::npos ? tag.substr(0, last) : tag.substr(before + 1, last - before - 1);
  long pid = 0;
  long counter = 0;
  if (!ParseNumber(pidText, pid) || pid <= 0 || !ParseNumber(tag.substr(last + 1), counter) ||
    host != Host() || pid == static_cast<long>(getpid()))
  {
    return false;
  }
  return kill(static_cast<pid_t>(pid), 0) != 0 && errno == ESRCH;
}
}

#endif
// VTK-HeaderTest-Exclude: vtkOFBTemporaryNames.h
