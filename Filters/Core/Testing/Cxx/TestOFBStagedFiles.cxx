// vtkOFBStagedFiles: files appear under their names only at Commit, in order; an
// uncommitted stage leaves nothing; a dead process's stage is removed by the next Begin; a
// target that cannot be written is refused with its cause before anything is staged.
#include "vtkOFBIOTestHelpers.h"

#include "vtkOFBStagedFiles.h"
#include "vtkOFBTemporaryNames.h"

#include <algorithm>

using namespace vtkofbtest;

namespace
{
std::string Read(const std::string& path)
{
  std::ifstream in(path, std::ios::binary);
  return std::string(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
}

bool IsStage(const std::string& name)
{
  return name.find(".tmp-") != std::string::npos;
}
}

TEST(StagedFiles, CommitPutsTheFilesInPlaceAndRemovesTheStage)
{
  TempDirectory dir;
  Save(dir.File("a.obj"), Bytes{ 'o', 'l', 'd' }, 3);
  vtkOFBStagedFiles files(dir.File("a.obj"));
  std::string message;
  ASSERT_TRUE(files.Begin({ "a.png", "a.obj" }, message)) << message;
  EXPECT_EQ(files.Final("a.png"), dir.File("a.png"));
  ASSERT_TRUE(files.Write("a.png", "texture", message)) << message;
  ASSERT_TRUE(files.Write("a.obj", "mesh", message)) << message;
  EXPECT_TRUE(files.Check("a.obj", message)) << message;
  // Staged, not yet in place: the old file is still there.
  EXPECT_EQ(Read(dir.File("a.obj")), "old");
  EXPECT_FALSE(vtksys::SystemTools::FileExists(dir.File("a.png")));
  ASSERT_TRUE(files.Commit({ "a.png", "a.obj" }, message)) << message;
  EXPECT_EQ(Read(dir.File("a.png")), "texture");
  EXPECT_EQ(Read(dir.File("a.obj")), "mesh");
  const std::vector<std::string> names = dir.List();
  EXPECT_EQ(std::count_if(names.begin(), names.end(), IsStage), 0);
}

TEST(StagedFiles, WithoutCommitNothingIsLeft)
{
  TempDirectory dir;
  {
    vtkOFBStagedFiles files(dir.File("b.ply"));
    std::string message;
    ASSERT_TRUE(files.Begin({ "b.ply" }, message)) << message;
    ASSERT_TRUE(files.Write("b.ply", "partial", message)) << message;
    EXPECT_EQ(dir.List().size(), 1u); // the stage
  }
  EXPECT_TRUE(dir.List().empty());
}

TEST(StagedFiles, EmptyFileIsIncompleteAndStaleStagesAreRemoved)
{
  TempDirectory dir;
  // Stages killed processes left (no process has this id): of this machine, in the names
  // written now and without a host, and of another machine (a shared folder), whose
  // process cannot be asked from here.
  const std::string stale = dir.File(".c.vtp.tmp-999999999-0");
  const std::string staleHere = dir.File(".d.vtp.tmp-" + vtkofbtemporary::Host() + "-999999999-1");
  const std::string elsewhere = dir.File(".e.vtp.tmp-other.host-999999999-2");
  for (const std::string& stage : { stale, staleHere, elsewhere })
  {
    ASSERT_TRUE(vtksys::SystemTools::MakeDirectory(stage));
    Save(stage + "/c.vtp", Bytes{ 'x' }, 1);
  }
  vtkOFBStagedFiles files(dir.File("c.vtp"));
  std::string message;
  ASSERT_TRUE(files.Begin({ "c.vtp" }, message)) << message;
  EXPECT_FALSE(vtksys::SystemTools::FileExists(stale));
  EXPECT_FALSE(vtksys::SystemTools::FileExists(staleHere));
  EXPECT_TRUE(vtksys::SystemTools::FileExists(elsewhere));
  // This process's own stage carries the machine's name.
  EXPECT_NE(files.Staged("c.vtp").find(".tmp-" + vtkofbtemporary::Host() + "-"), std::string::npos);
  Save(files.Staged("c.vtp"), Bytes{}, 0);
  EXPECT_FALSE(files.Check("c.vtp", message));
  EXPECT_NE(message.find("empty"), std::string::npos) << message;
}

TEST(StagedFiles, UnwritableTargetsAreRefusedWithTheirCause)
{
  TempDirectory dir;
  ASSERT_TRUE(vtksys::SystemTools::MakeDirectory(dir.File("d.obj")));
  vtkOFBStagedFiles files(dir.File("d.obj"));
  std::string message;
  EXPECT_FALSE(files.Begin({ "d.obj" }, message));
  EXPECT_NE(message.find("it is a directory"), std::string::npos) << message;
  EXPECT_NE(vtkOFBStagedFiles::WhyNotWritable(dir.File("missing/e.obj")), "");
  EXPECT_EQ(vtkOFBStagedFiles::WhyNotWritable(dir.File("e.obj")), "");
  EXPECT_EQ(dir.List().size(), 1u); // the directory alone: nothing staged
}
