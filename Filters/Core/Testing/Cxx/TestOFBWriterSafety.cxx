// vtkOFBWriter's replacement of a file: a writer killed mid-write leaves the old file and
// no temporary, stale temporaries of dead writers are removed, the replaced file keeps its
// permissions, a symbolic link is written through, and a target that is not a regular file
// (a FIFO, a device, a directory) is refused and left as it is.
#include "vtkOFBIOTestHelpers.h"
#include "vtkOFBTemporaryNames.h"

#include <algorithm>

#if !defined(_WIN32)
#include <fcntl.h>
#include <poll.h>
#include <signal.h>
#include <sys/stat.h>
#include <sys/sysmacros.h>
#include <sys/wait.h>
#endif

using namespace vtkofbtest;

#if !defined(_WIN32)
namespace
{
/// Once the file is partly written, tell the parent through a pipe, then wait to be killed.
class StopMidWrite : public vtkCommand
{
public:
  static StopMidWrite* New() { return new StopMidWrite; }
  void Execute(vtkObject*, unsigned long, void* data) override
  {
    const double progress = *static_cast<double*>(data);
    if (progress > 0.0 && progress < 1.0)
    {
      const char byte = 'w';
      (void)!write(this->Pipe, &byte, 1);
      for (;;)
      {
        pause();
      }
    }
  }
  int Pipe = -1;
};

/// Whether the writer can use an unnamed temporary file in `directory`.
bool UnnamedFilesSupported(const std::string& directory)
{
#if defined(O_TMPFILE)
  const int fd = open(directory.c_str(), O_TMPFILE | O_WRONLY, 0600);
  if (fd >= 0)
  {
    close(fd);
    return access("/proc/self/fd", X_OK) == 0;
  }
#endif
  (void)directory;
  return false;
}

/// The id of a process that has ended.
pid_t DeadProcess()
{
  const pid_t child = fork();
  if (child == 0)
  {
    _exit(0);
  }
  int status = 0;
  waitpid(child, &status, 0);
  return child;
}

std::vector<std::string> Sorted(std::vector<std::string> names)
{
  std::sort(names.begin(), names.end());
  return names;
}

mode_t Permissions(const std::string& path)
{
  struct stat info;
  return stat(path.c_str(), &info) == 0 ? (info.st_mode & 07777) : 0;
}
}

TEST(WriterSafety, KilledMidWriteLeavesTheOldFileAndNoTemporary)
{
  TempDirectory dir;
  const std::string path = dir.File("a.ofb");
  ASSERT_EQ(WriteOFB(SmallOFB(), path), "");
  const Bytes original = Load(path);
  vtkSmartPointer<vtkOFB> other = Build(MakeSphere(1.0, 16), 40);

  int ready[2];
  ASSERT_EQ(pipe(ready), 0);
  const pid_t child = fork();
  ASSERT_GE(child, 0);
  if (child == 0)
  {
    close(ready[0]);
    vtkNew<vtkOFBWriter> writer;
    vtkNew<StopMidWrite> stop;
    stop->Pipe = ready[1];
    writer->AddObserver(vtkCommand::ProgressEvent, stop);
    writer->SetInputData(other);
    writer->SetFileName(path.c_str());
    writer->Write();
    _exit(3); // the write ended without reaching its middle
  }
  close(ready[1]);
  struct pollfd wait = { ready[0], POLLIN, 0 };
  char byte = 0;
  const bool midWrite = poll(&wait, 1, 60000) == 1 && read(ready[0], &byte, 1) == 1;
  kill(child, SIGKILL);
  int status = 0;
  waitpid(child, &status, 0);
  close(ready[0]);
  ASSERT_TRUE(midWrite) << "the writer did not report progress in the middle of the file";
  EXPECT_TRUE(WIFSIGNALED(status) && WTERMSIG(status) == SIGKILL);

  // The old file is intact.
  EXPECT_EQ(Load(path), original);
  std::string errors;
  ReadOFB(path, errors);
  EXPECT_EQ(errors, "");
  const std::vector<std::string> left = Sorted(dir.List());
  if (UnnamedFilesSupported(dir.Path))
  {
    // The partial file had no name: nothing is left behind.
    EXPECT_EQ(left, std::vector<std::string>{ "a.ofb" });
  }
  else
  {
    // The dead writer's named temporary is left, until the next write.
    ASSERT_EQ(left.size(), 2u);
    EXPECT_EQ(left[1], "a.ofb.tmp-" + vtkofbtemporary::Host() + "-" + std::to_string(child) + "-0");
  }
  // The next write replaces the file and leaves only it.
  ASSERT_EQ(WriteOFB(other, path), "");
  EXPECT_EQ(dir.List(), std::vector<std::string>{ "a.ofb" });
  ExpectSameOFB(other, ReadOFB(path, errors));
}

TEST(WriterSafety, RemovesStaleTemporariesOfDeadProcessesOnly)
{
  TempDirectory dir;
  const std::string dead = std::to_string(DeadProcess());
  const std::string alive = std::to_string(getpid());
  const Bytes junk = { 'p', 'a', 'r', 't' };
  const std::vector<std::string> temporaries = {
    "a.ofb.tmp-" + dead + "-0",                                  // a dead writer's: removed
    "a.ofb.tmp-" + dead + "-12",                                 // removed
    "a.ofb.tmp-" + alive + "-7",                                 // a living process's: kept
    "b.ofb.tmp-" + dead + "-0",                                  // another file's: kept
    "a.ofb.tmp-" + dead + "-x",                                  // not a writer's name: kept
    "a.ofb.tmp-other.host-" + dead + "-0",                       // another machine's: kept
    "a.ofb.tmp-" + vtkofbtemporary::Host() + "-" + dead + "-3",  // this machine's: removed
    "a.ofb.tmp-" + vtkofbtemporary::Host() + "-" + alive + "-4", // living: kept
  };
  for (const std::string& name : temporaries)
  {
    Save(dir.File(name), junk, junk.size());
  }
  ASSERT_EQ(WriteOFB(SmallOFB(), dir.File("a.ofb")), "");
  EXPECT_EQ(Sorted(dir.List()),
    Sorted(
      { "a.ofb", temporaries[2], temporaries[3], temporaries[4], temporaries[5], temporaries[7] }));
}

TEST(WriterSafety, KeepsThePermissionsOfTheFileItReplaces)
{
  TempDirectory dir;
  const std::string path = dir.File("a.ofb");
  vtkSmartPointer<vtkOFB> ofb = SmallOFB();
  const mode_t mask = umask(022);
  umask(mask);
  ASSERT_EQ(WriteOFB(ofb, path), "");
  EXPECT_EQ(Permissions(path), 0666 & ~mask) << "a new file gets 0666 less the umask";
  for (const mode_t mode : { 0600, 0640, 0604 })
  {
    ASSERT_EQ(chmod(path.c_str(), mode), 0);
    ASSERT_EQ(WriteOFB(ofb, path), "");
    EXPECT_EQ(Permissions(path), mode);
  }
  EXPECT_EQ(dir.List(), std::vector<std::string>{ "a.ofb" });
}

TEST(WriterSafety, WritesThroughASymbolicLink)
{
  TempDirectory dir;
  vtkSmartPointer<vtkOFB> first = SmallOFB();
  vtkSmartPointer<vtkOFB> second = Build(MakeSphere(1.0, 16), 40);
  ASSERT_EQ(WriteOFB(first, dir.File("real.ofb")), "");
  ASSERT_EQ(chmod(dir.File("real.ofb").c_str(), 0600), 0);
  // A relative link, and a link to that link.
  ASSERT_EQ(symlink("real.ofb", dir.File("link.ofb").c_str()), 0);
  ASSERT_EQ(symlink(dir.File("link.ofb").c_str(), dir.File("chain.ofb").c_str()), 0);

  ASSERT_EQ(WriteOFB(second, dir.File("chain.ofb")), "");
  struct stat info;
  ASSERT_EQ(lstat(dir.File("chain.ofb").c_str(), &info), 0);
  EXPECT_TRUE(S_ISLNK(info.st_mode));
  ASSERT_EQ(lstat(dir.File("link.ofb").c_str(), &info), 0);
  EXPECT_TRUE(S_ISLNK(info.st_mode));
  std::string errors;
  ExpectSameOFB(second, ReadOFB(dir.File("real.ofb"), errors));
  EXPECT_EQ(Permissions(dir.File("real.ofb")), 0600u);

  // A link to a file that does not exist yet creates the file.
  ASSERT_EQ(symlink("new.ofb", dir.File("dangling.ofb").c_str()), 0);
  ASSERT_EQ(WriteOFB(first, dir.File("dangling.ofb")), "");
  ASSERT_EQ(lstat(dir.File("dangling.ofb").c_str(), &info), 0);
  EXPECT_TRUE(S_ISLNK(info.st_mode));
  ExpectSameOFB(first, ReadOFB(dir.File("new.ofb"), errors));
  EXPECT_EQ(
    Sorted(dir.List()), Sorted({ "real.ofb", "link.ofb", "chain.ofb", "dangling.ofb", "new.ofb" }));
}

namespace
{
/// The type bits of `path` itself (not following a link), or 0 if it does not exist.
mode_t FileType(const std::string& path)
{
  struct stat info;
  return lstat(path.c_str(), &info) == 0 ? (info.st_mode & S_IFMT) : 0;
}

/// Writing to `target` must be refused with `expected` in the error, leaving `target`
/// (of type `type`) as it was and nothing else in `dir` but `names`.
void ExpectRefusedTarget(const TempDirectory& dir,
  const std::string& target,
  mode_t type,
  const std::string& expected,
  const std::vector<std::string>& names)
{
  int result = 1;
  const std::string errors = WriteOFB(SmallOFB(), target, &result);
  EXPECT_NE(errors.find(expected), std::string::npos) << errors;
  EXPECT_NE(errors.find("not a regular file"), std::string::npos) << errors;
  EXPECT_EQ(result, 0);
  EXPECT_EQ(FileType(target), type);
  EXPECT_EQ(Sorted(dir.List()), Sorted(names));
}
}

TEST(WriterSafety, RefusesAFIFO)
{
  TempDirectory dir;
  const std::string fifo = dir.File("pipe.ofb");
  ASSERT_EQ(mkfifo(fifo.c_str(), 0600), 0);
  // Opening the FIFO to write would block without a reader: the writer must not.
  ExpectRefusedTarget(dir, fifo, S_IFIFO, "is a FIFO", { "pipe.ofb" });
  // Nor through a symbolic link, which is kept.
  ASSERT_EQ(symlink("pipe.ofb", dir.File("link.ofb").c_str()), 0);
  ExpectRefusedTarget(dir, dir.File("link.ofb"), S_IFLNK, "is a FIFO", { "pipe.ofb", "link.ofb" });
  EXPECT_EQ(FileType(fifo), static_cast<mode_t>(S_IFIFO));
  // Reading it is refused at once too (opening it would wait for a writer).
  ExpectReadError(fifo, "not a regular file");
  EXPECT_FALSE(vtkOFBReader::CanReadFile(fifo.c_str()));
}

TEST(WriterSafety, RefusesACharacterDevice)
{
  if (geteuid() != 0)
  {
    GTEST_SKIP() << "making a device (mknod) needs root";
  }
  TempDirectory dir;
  const std::string device = dir.File("null.ofb");
  // The same device as /dev/null (major 1, minor 3).
  if (mknod(device.c_str(), S_IFCHR | 0666, makedev(1, 3)) != 0)
  {
    GTEST_SKIP() << "mknod refused (" << std::strerror(errno) << "): no CAP_MKNOD here";
  }
  ExpectRefusedTarget(dir, device, S_IFCHR, "is a character device", { "null.ofb" });
  struct stat info;
  ASSERT_EQ(stat(device.c_str(), &info), 0);
  EXPECT_EQ(info.st_rdev, makedev(1, 3));
}

TEST(WriterSafety, RefusesADirectory)
{
  TempDirectory dir;
  const std::string directory = dir.File("out.ofb");
  ASSERT_TRUE(vtksys::SystemTools::MakeDirectory(directory));
  ExpectRefusedTarget(dir, directory, S_IFDIR, "is a directory", { "out.ofb" });
  EXPECT_EQ(vtksys::SystemTools::FileExists(directory + "/anything"), false);
}
#endif
