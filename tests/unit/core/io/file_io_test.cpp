// Tests for whole-file reads, atomic writes and baseName. Each test works in
// its own scratch directory so leftover temporary files can be detected.
#include "core/io/file_io.h"

#include <dirent.h>
#include <fcntl.h>
#include <gtest/gtest.h>
#include <sys/file.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <cerrno>
#include <chrono>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <new>
#include <regex>
#include <string>
#include <thread>
#include <vector>

namespace smpl {
namespace {

class FileIo : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = ::testing::TempDir() + "file_io_test_" + std::to_string(::getpid()) + "_" +
           ::testing::UnitTest::GetInstance()->current_test_info()->name();
    ::mkdir(dir_.c_str(), 0755);
  }
  void TearDown() override {
    for (const std::string& f : list()) std::remove((dir_ + "/" + f).c_str());
    ::rmdir((dir_ + "/sub").c_str());
    ::rmdir((dir_ + "/out.glb.smpl.json").c_str());
    ::rmdir(dir_.c_str());
  }
  std::vector<std::string> list() const {
    std::vector<std::string> names;
    if (DIR* d = ::opendir(dir_.c_str())) {
      while (dirent* e = ::readdir(d))
        if (std::strcmp(e->d_name, ".") && std::strcmp(e->d_name, "..")) names.push_back(e->d_name);
      ::closedir(d);
    }
    return names;
  }
  std::string dir_;
};

std::string readText(const std::string& path) {
  Result<std::vector<uint8_t>> r = readFileBytes(path);
  return r ? std::string(r->begin(), r->end()) : "<" + r.message() + ">";
}

TEST_F(FileIo, WriteThenReadRoundTripsBinaryData) {
  std::string bytes(300000, '\0');  // larger than the read chunk, with NULs
  for (size_t i = 0; i < bytes.size(); ++i) bytes[i] = static_cast<char>((i * 131) & 0xff);
  const std::string path = dir_ + "/out.glb";
  ASSERT_TRUE(writeFileAtomic(path, bytes).ok());
  Result<std::vector<uint8_t>> back = readFileBytes(path);
  ASSERT_TRUE(back.ok()) << back.message();
  EXPECT_EQ(std::string(back->begin(), back->end()), bytes);
  EXPECT_EQ(list(), std::vector<std::string>{"out.glb"});  // no temporary left behind
}

// A file given in parts (a GLB's head, its BIN chunk, the asset's arrays
// spliced in) is written as their concatenation, in order.
TEST_F(FileIo, AFileInPartsIsWrittenAsTheirConcatenation) {
  const std::string head = "glTF head|", a(200000, 'b'), b = "|spliced|", c(70000, 'c');
  const std::string path = dir_ + "/parts.glb";
  const FileContent f{
      path,
      head.data(),
      head.size(),
      {{a.data(), a.size()}, {b.data(), b.size()}, {nullptr, 0}, {c.data(), c.size()}}};
  EXPECT_EQ(f.totalSize(), head.size() + a.size() + b.size() + c.size());
  ASSERT_TRUE(writeFilesTogether({f}).ok());
  EXPECT_EQ(readText(path), head + a + b + c);
  EXPECT_EQ(list(), std::vector<std::string>{"parts.glb"});
}

TEST_F(FileIo, OverwritesAnExistingFile) {
  const std::string path = dir_ + "/x.json";
  ASSERT_TRUE(writeFileAtomic(path, std::string("a much longer first version")).ok());
  ASSERT_TRUE(writeFileAtomic(path, std::string("v2")).ok());
  Result<std::vector<uint8_t>> back = readFileBytes(path);
  ASSERT_TRUE(back.ok());
  EXPECT_EQ(std::string(back->begin(), back->end()), "v2");
}

TEST_F(FileIo, EmptyFileReadsAsEmpty) {
  const std::string path = dir_ + "/empty";
  ASSERT_TRUE(writeFileAtomic(path, std::string()).ok());
  Result<std::vector<uint8_t>> back = readFileBytes(path);
  ASSERT_TRUE(back.ok());
  EXPECT_TRUE(back->empty());
}

TEST_F(FileIo, MissingFileReportsPathAndReason) {
  const std::string path = dir_ + "/nope.npz";
  Result<std::vector<uint8_t>> r = readFileBytes(path);
  ASSERT_FALSE(r.ok());
  EXPECT_EQ(r.message(), path + ": cannot open: " + std::strerror(ENOENT));
}

TEST_F(FileIo, ReadingADirectoryIsAnError) {
  Result<std::vector<uint8_t>> r = readFileBytes(dir_);
  ASSERT_FALSE(r.ok());
  EXPECT_EQ(r.message(), dir_ + ": not a regular file (a directory)");
}

TEST_F(FileIo, WriteIntoMissingDirectoryFailsCleanly) {
  const std::string path = dir_ + "/no/such/dir/out.glb";
  Status st = writeFileAtomic(path, std::string("x"));
  ASSERT_FALSE(st.ok());
  EXPECT_EQ(st.message().rfind(path + ": cannot create temporary file: ", 0), 0u) << st.message();
  EXPECT_TRUE(list().empty());
}

TEST_F(FileIo, FailedRenameRemovesTheTemporary) {
  const std::string path = dir_ + "/sub";  // a non-empty directory cannot be replaced by a file
  ASSERT_EQ(::mkdir(path.c_str(), 0755), 0);
  std::ofstream(path + "/keep") << "x";
  Status st = writeFileAtomic(path, std::string("data"));
  ASSERT_FALSE(st.ok());
  EXPECT_NE(st.message().find(path + ": cannot rename temporary file into place"),
            std::string::npos)
      << st.message();
  EXPECT_EQ(list(), std::vector<std::string>{"sub"});
  std::remove((path + "/keep").c_str());
}

// "<dir>/.<name>.smpl.tmp-<8 hex tag>-<16 hex random>": named after the output,
// a new unpredictable name every time, and short enough for any legal name.
TEST_F(FileIo, TemporaryIsDotPrefixedNamedAfterTheOutputAndUnpredictable) {
  const std::regex pattern(R"(/data/out/\.walk\.glb\.smpl\.tmp-[0-9a-f]{8}-[0-9a-f]{16})");
  const std::string a = tempPathFor("/data/out/walk.glb"), b = tempPathFor("/data/out/walk.glb");
  EXPECT_TRUE(std::regex_match(a, pattern)) << a;
  EXPECT_NE(a, b);
  EXPECT_EQ(a.substr(0, a.size() - 16), b.substr(0, b.size() - 16));  // same output, same tag
  EXPECT_EQ(a.find(std::to_string(::getpid())), std::string::npos);   // no pid in the name
  EXPECT_EQ(tempPathFor("walk.glb").rfind(".walk.glb.smpl.tmp-", 0), 0u);
  // Every legal name (255 bytes) has a temporary whose backup ("-old") fits too.
  const std::string longest(255, 'n');
  EXPECT_LE(baseName(tempPathFor("/d/" + longest)).size() + 4, 255u);
  // Names that differ only after the cut still get different temporaries (the tag).
  const std::string p1 = tempPathFor("/d/" + longest),
                    p2 = tempPathFor("/d/" + longest.substr(1) + "m");
  EXPECT_NE(p1.substr(0, p1.size() - 16), p2.substr(0, p2.size() - 16));
}

// Legal output names of 229..255 bytes are written (the temporary's name was
// too long before); 256 bytes is refused before anything is created.
TEST_F(FileIo, LongestLegalNamesAreWritten) {
  for (size_t n : {229u, 245u, 255u}) {
    const std::string path = dir_ + "/" + std::string(n - 4, 'a') + ".glb";
    Status st = writeFileAtomic(path, std::string("x"));
    EXPECT_TRUE(st.ok()) << n << ": " << st.message();
    EXPECT_EQ(readText(path), "x");
    std::remove(path.c_str());
  }
  const std::string too_long = dir_ + "/" + std::string(256, 'a');
  Status st = writeFileAtomic(too_long, std::string("x"));
  ASSERT_FALSE(st.ok());
  EXPECT_NE(st.message().find(std::strerror(ENAMETOOLONG)), std::string::npos) << st.message();
  EXPECT_TRUE(list().empty());
}

TEST_F(FileIo, PairIsWrittenTogether) {
  const std::string out = dir_ + "/out.glb", side = out + ".smpl.json";
  const std::string a = "output v1", b = "sidecar v1";
  ASSERT_TRUE(writeFilesTogether({{out, a.data(), a.size()}, {side, b.data(), b.size()}}).ok());
  EXPECT_EQ(readText(out), a);
  EXPECT_EQ(readText(side), b);
  EXPECT_EQ(list().size(), 2u);  // no temporaries or backups left
}

// The sidecar cannot be renamed into place (a directory is in the way): the
// new output must be rolled back, so the old output stays, byte for byte.
TEST_F(FileIo, FailedSidecarKeepsTheOldOutput) {
  const std::string out = dir_ + "/out.glb", side = out + ".smpl.json";
  ASSERT_TRUE(writeFileAtomic(out, std::string("old output")).ok());
  ASSERT_EQ(::mkdir(side.c_str(), 0755), 0);
  std::ofstream(side + "/keep") << "x";
  const std::string a = "new output", b = "new sidecar";
  Status st = writeFilesTogether({{out, a.data(), a.size()}, {side, b.data(), b.size()}});
  std::remove((side + "/keep").c_str());
  ASSERT_FALSE(st.ok());
  EXPECT_NE(st.message().find(side + ": cannot rename temporary file into place"),
            std::string::npos)
      << st.message();
  EXPECT_EQ(readText(out), "old output");
  std::vector<std::string> names = list();
  std::sort(names.begin(), names.end());
  EXPECT_EQ(names, (std::vector<std::string>{"out.glb", "out.glb.smpl.json"}));  // no temporaries
}

// Same with no previous output: the new one must not stay alone.
TEST_F(FileIo, FailedSidecarLeavesNoNewOutput) {
  const std::string out = dir_ + "/out.glb", side = out + ".smpl.json";
  ASSERT_EQ(::mkdir(side.c_str(), 0755), 0);
  std::ofstream(side + "/keep") << "x";
  const std::string a = "new output", b = "new sidecar";
  Status st = writeFilesTogether({{out, a.data(), a.size()}, {side, b.data(), b.size()}});
  std::remove((side + "/keep").c_str());
  ASSERT_FALSE(st.ok());
  EXPECT_EQ(list(), std::vector<std::string>{"out.glb.smpl.json"});
}

// The record (the last file) is made while the others are written: it can
// read their bytes, and it is committed with them, last.
TEST_F(FileIo, RecordIsMadeFromTheFilesAndWrittenWithThem) {
  const std::string out = dir_ + "/out.glb", side = out + ".smpl.json";
  const std::string a = "new output";
  for (const bool together : {false, true}) {
    const std::vector<FileContent> files = {{out, a.data(), a.size()}};
    const Status st = writeFilesWithRecord(
        files, side,
        [&] {
          return "record of " + std::string(static_cast<const char*>(files[0].data), files[0].size);
        },
        together);
    ASSERT_TRUE(st.ok()) << st.message();
    EXPECT_EQ(readText(out), a);
    EXPECT_EQ(readText(side), "record of new output");
    EXPECT_EQ(list().size(), 2u);  // no temporaries or backups left
  }
}

// A record that cannot be made (it throws) leaves the old pair and no
// temporary, however far the other files' writes got.
TEST_F(FileIo, RecordThatThrowsLeavesTheOldFiles) {
  const std::string out = dir_ + "/out.glb", side = out + ".smpl.json";
  ASSERT_TRUE(writeFileAtomic(out, std::string("old output")).ok());
  ASSERT_TRUE(writeFileAtomic(side, std::string("old sidecar")).ok());
  const std::string a(1 << 20, 'x');
  for (const bool together : {false, true}) {
    EXPECT_THROW((void)writeFilesWithRecord(
                     {{out, a.data(), a.size()}}, side,
                     []() -> std::string { throw std::bad_alloc(); }, together),
                 std::bad_alloc);
    EXPECT_EQ(readText(out), "old output");
    EXPECT_EQ(readText(side), "old sidecar");
    EXPECT_EQ(list().size(), 2u);
  }
}

// A record whose name is too long fails before any file is created.
TEST_F(FileIo, RecordNameTooLongFailsFirst) {
  const std::string out = dir_ + "/out.glb", side = dir_ + "/" + std::string(300, 's');
  const std::string a = "new output";
  bool made = false;
  const Status st = writeFilesWithRecord(
      {{out, a.data(), a.size()}}, side, [&] { return made = true, std::string("r"); }, true);
  ASSERT_FALSE(st.ok());
  EXPECT_NE(st.message().find(std::strerror(ENAMETOOLONG)), std::string::npos) << st.message();
  EXPECT_FALSE(made);
  EXPECT_TRUE(list().empty());
}

// A failed first rename (output is a directory) leaves the old sidecar.
TEST_F(FileIo, FailedOutputKeepsTheOldSidecar) {
  const std::string out = dir_ + "/sub", side = out + ".smpl.json";
  ASSERT_TRUE(writeFileAtomic(side, std::string("old sidecar")).ok());
  ASSERT_EQ(::mkdir(out.c_str(), 0755), 0);
  std::ofstream(out + "/keep") << "x";
  const std::string a = "new output", b = "new sidecar";
  Status st = writeFilesTogether({{out, a.data(), a.size()}, {side, b.data(), b.size()}});
  std::remove((out + "/keep").c_str());
  ASSERT_FALSE(st.ok());
  EXPECT_EQ(readText(side), "old sidecar");
  EXPECT_EQ(list().size(), 2u);
}

// Stale temporaries (and backups) of our outputs, which no one holds locked,
// go; a live writer's (locked), other outputs', links, folders and files that
// only look similar stay.
TEST_F(FileIo, RemovesOnlyStaleTemporariesOfItsOutputs) {
  const std::string out = dir_ + "/out.glb", side = out + ".smpl.json";
  const std::string stale = tempPathFor(out), stale_side = tempPathFor(side),
                    stale_backup = tempPathFor(out) + "-old", live = tempPathFor(side),
                    other = tempPathFor(dir_ + "/other.glb"), link = tempPathFor(out),
                    folder = tempPathFor(out);
  for (const std::string& f : {stale, stale_side, stale_backup, live, other})
    std::ofstream(f) << "x";
  ASSERT_EQ(::symlink("out.glb", link.c_str()), 0);
  ASSERT_EQ(::mkdir(folder.c_str(), 0755), 0);
  const std::vector<std::string> similar = {baseName(stale) + "x", baseName(stale).substr(1),
                                            ".out.glb.smpl.tmp-" + std::to_string(::getpid()),
                                            baseName(stale).substr(0, baseName(stale).size() - 1)};
  for (const std::string& f : similar) std::ofstream(dir_ + "/" + f) << "x";
  const int held = ::open(live.c_str(), O_RDONLY | O_CLOEXEC);  // a live writer's lock
  ASSERT_EQ(::flock(held, LOCK_EX), 0);
  const int removed = removeStaleTemps(dir_, {"out.glb", "out.glb.smpl.json"});
  ::close(held);
  EXPECT_EQ(removed, 3);
  std::vector<std::string> left = list();
  std::sort(left.begin(), left.end());
  std::vector<std::string> want = {baseName(live), baseName(other), baseName(link),
                                   baseName(folder)};
  want.insert(want.end(), similar.begin(), similar.end());
  std::sort(want.begin(), want.end());
  EXPECT_EQ(left, want);
  ::rmdir(folder.c_str());
}

// A write holds its temporary locked until the commit: a cleanup running at
// the same time (another process's removeStaleTemps) must not take it.
TEST_F(FileIo, LiveTemporaryIsNotRemovedByACleanupMeanwhile) {
  // The random source runs while the write creates its temporary; the cleanup
  // here runs right after (the name is known), before any byte is written.
  setTempRandomForTesting(+[]() -> std::string { return "00000000000000aa"; });
  const std::string out = dir_ + "/out.glb";
  std::vector<uint8_t> big(64 << 20, 7);  // long enough to clean while it is written
  std::thread writer([&] { EXPECT_TRUE(writeFileAtomic(out, big.data(), big.size()).ok()); });
  const std::string temp = tempPathFor(out);  // the same name (fixed random part)
  struct stat st {};
  for (int i = 0; i < 100000 && ::lstat(temp.c_str(), &st) != 0; ++i) std::this_thread::yield();
  const bool seen = ::lstat(temp.c_str(), &st) == 0;
  const int removed = seen ? removeStaleTemps(dir_, {"out.glb"}) : -1;
  writer.join();
  setTempRandomForTesting(nullptr);
  EXPECT_TRUE(seen);
  EXPECT_EQ(removed, 0);
  EXPECT_EQ(readText(out).size(), big.size());
}

// O_CREAT | O_EXCL | O_NOFOLLOW: a symbolic link (or a file) planted under the
// very name the write draws is never followed or truncated; the write draws
// another name, and the link's target is untouched.
TEST_F(FileIo, PlantedLinkAtTheTemporaryNameIsNeverFollowed) {
  static int calls = 0;
  calls = 0;
  setTempRandomForTesting(+[]() -> std::string {
    return ++calls <= 2 ? "0000000000000001" : "0000000000000002";  // 1st, 2nd draw: planted
  });
  const std::string out = dir_ + "/out.glb", target = dir_ + "/outside.txt";
  std::ofstream(target) << "precious";
  const std::string planted = tempPathFor(out);  // draw 1: the name the write draws first
  ASSERT_EQ(::symlink(target.c_str(), planted.c_str()), 0);
  Status st = writeFileAtomic(out, std::string("new output"));  // draw 2: planted, 3: free
  setTempRandomForTesting(nullptr);
  ASSERT_TRUE(st.ok()) << st.message();
  EXPECT_EQ(readText(target), "precious");
  EXPECT_EQ(readText(out), "new output");
  struct stat ls {};
  ASSERT_EQ(::lstat(out.c_str(), &ls), 0);
  EXPECT_TRUE(S_ISREG(ls.st_mode));
  ASSERT_EQ(::lstat(planted.c_str(), &ls), 0);
  EXPECT_TRUE(S_ISLNK(ls.st_mode));  // the planted link itself is left as it was
  EXPECT_EQ(calls, 3);
}

// A symbolic link at the output's (or the sidecar's) own name is replaced by
// the new file; its target outside the folder is never written.
TEST_F(FileIo, LinkAtTheOutputNameIsReplacedNotFollowed) {
  const std::string out = dir_ + "/out.glb", side = out + ".smpl.json";
  const std::string target = dir_ + "/outside.txt";
  std::ofstream(target) << "precious";
  ASSERT_EQ(::symlink(target.c_str(), out.c_str()), 0);
  ASSERT_EQ(::symlink(target.c_str(), side.c_str()), 0);
  const std::string a = "new output", b = "new sidecar";
  ASSERT_TRUE(writeFilesTogether({{out, a.data(), a.size()}, {side, b.data(), b.size()}}).ok());
  EXPECT_EQ(readText(target), "precious");
  for (const std::string& p : {out, side}) {
    struct stat ls {};
    ASSERT_EQ(::lstat(p.c_str(), &ls), 0);
    EXPECT_TRUE(S_ISREG(ls.st_mode)) << p;
  }
  EXPECT_EQ(readText(out), a);
  EXPECT_EQ(list().size(), 3u);  // no temporaries or backups left
}

// Two writers of the same pair at once (threads here; processes in the
// reliability suite): commits are serialised, so after every race the pair on
// disk comes from one writer.
TEST_F(FileIo, ConcurrentWritersLeaveOneConsistentPair) {
  const std::string out = dir_ + "/out.glb", side = out + ".smpl.json";
  int mixed = 0;
  for (int race = 0; race < 100; ++race) {
    std::vector<std::thread> writers;
    for (int w = 0; w < 2; ++w)
      writers.emplace_back([&, w] {
        const std::string a = "output of " + std::to_string(w),
                          b = "sidecar of " + std::to_string(w);
        EXPECT_TRUE(
            writeFilesTogether({{out, a.data(), a.size()}, {side, b.data(), b.size()}}).ok());
      });
    for (std::thread& t : writers) t.join();
    const std::string a = readText(out), b = readText(side);
    if (a.substr(a.size() - 1) != b.substr(b.size() - 1)) ++mixed;
  }
  EXPECT_EQ(mixed, 0);
  EXPECT_EQ(list().size(), 2u);
}

// The interleaving the folder lock exists for, forced: writer 0 pauses after
// renaming its output into place (the commit hook), writer 1 starts its whole
// write then. Without the lock writer 1 renames both files during the pause and
// writer 0's sidecar lands last: output of 1 beside sidecar of 0. With it,
// writer 1 waits and the pair that stays is writer 1's, whole.
std::atomic<bool> g_paused{false};
std::atomic<bool> g_release{false};

void pauseAfterFirstRename(size_t index) {
  if (index != 0 || g_paused.exchange(true)) return;  // only writer 0's first rename
  for (int i = 0; i < 400 && !g_release.load(); ++i)
    std::this_thread::sleep_for(std::chrono::milliseconds(1));
}

TEST_F(FileIo, SecondWriterWaitsForACommitInProgress) {
  const std::string out = dir_ + "/out.glb", side = out + ".smpl.json";
  g_paused = false;
  g_release = false;
  setCommitHookForTesting(pauseAfterFirstRename);
  const std::string a0 = "output of 0", b0 = "sidecar of 0", a1 = "output of 1",
                    b1 = "sidecar of 1";
  std::thread first([&] {
    EXPECT_TRUE(
        writeFilesTogether({{out, a0.data(), a0.size()}, {side, b0.data(), b0.size()}}).ok());
  });
  while (!g_paused.load()) std::this_thread::sleep_for(std::chrono::milliseconds(1));
  std::thread second([&] {
    EXPECT_TRUE(
        writeFilesTogether({{out, a1.data(), a1.size()}, {side, b1.data(), b1.size()}}).ok());
  });
  std::this_thread::sleep_for(std::chrono::milliseconds(150));  // writer 1 would be done by now
  g_release = true;
  first.join();
  second.join();
  setCommitHookForTesting(nullptr);
  EXPECT_EQ(readText(out), a1);
  EXPECT_EQ(readText(side), b1);
  EXPECT_EQ(list().size(), 2u);
}

// The folder of a set is opened once and every file is created and renamed
// relative to that handle: a folder moved away and replaced by a link to
// another place between two renames (a planted link) cannot redirect the
// rest of the set; both files end in the folder the write began in.
std::string g_swap_from, g_swap_to, g_swap_link_target;

void swapFolderForLink(size_t index) {
  if (index != 0) return;
  ASSERT_EQ(::rename(g_swap_from.c_str(), g_swap_to.c_str()), 0);
  ASSERT_EQ(::symlink(g_swap_link_target.c_str(), g_swap_from.c_str()), 0);
}

TEST_F(FileIo, FolderSwappedForALinkMidCommitCannotRedirectTheSet) {
  const std::string sub = dir_ + "/set", moved = dir_ + "/set-moved", elsewhere = dir_ + "/else";
  ASSERT_EQ(::mkdir(sub.c_str(), 0755), 0);
  ASSERT_EQ(::mkdir(elsewhere.c_str(), 0755), 0);
  g_swap_from = sub, g_swap_to = moved, g_swap_link_target = elsewhere;
  setCommitHookForTesting(swapFolderForLink);
  const std::string out = "output", side = "sidecar";
  const Status st = writeFilesTogether({{sub + "/a.glb", out.data(), out.size()},
                                        {sub + "/a.glb.smpl.json", side.data(), side.size()}});
  setCommitHookForTesting(nullptr);
  EXPECT_TRUE(st.ok()) << st.message();
  EXPECT_EQ(readText(moved + "/a.glb"), out);
  EXPECT_EQ(readText(moved + "/a.glb.smpl.json"), side);
  std::vector<std::string> redirected;
  if (DIR* d = ::opendir(elsewhere.c_str())) {
    while (dirent* e = ::readdir(d))
      if (std::strcmp(e->d_name, ".") && std::strcmp(e->d_name, ".."))
        redirected.push_back(e->d_name);
    ::closedir(d);
  }
  EXPECT_TRUE(redirected.empty()) << redirected.front();
  for (const std::string& f : {moved + "/a.glb", moved + "/a.glb.smpl.json"})
    std::remove(f.c_str());
  for (const std::string& f : redirected) std::remove((elsewhere + "/" + f).c_str());
  ::unlink(sub.c_str());
  ::rmdir(moved.c_str());
  ::rmdir(elsewhere.c_str());
}

TEST(BaseName, LastPathComponent) {
  EXPECT_EQ(baseName("/data/models/SMPLX_NEUTRAL.npz"), "SMPLX_NEUTRAL.npz");
  EXPECT_EQ(baseName("model.npz"), "model.npz");
  EXPECT_EQ(baseName("rel/dir/beta.npy"), "beta.npy");
  EXPECT_EQ(baseName("dir/"), "dir");
  EXPECT_EQ(baseName("/"), "/");
  EXPECT_EQ(baseName(""), "");
}

}  // namespace
}  // namespace smpl
