// Helpers of the IO and command-line tests (not installed): a failure count with its check, and
// the files of a test's folder.
#ifndef FeaturePointsTestFiles_h
#define FeaturePointsTestFiles_h

#include <dirent.h>
#include <sys/stat.h>

#include <cstdio>
#include <fstream>
#include <set>
#include <sstream>
#include <string>

namespace fptest
{
/** The failed checks of this test. */
inline int Failures = 0;

/** Counts a failure and prints what failed when `ok` is false. */
inline void Check(bool ok, const std::string& what)
{
  if (!ok)
  {
    std::printf("FAILED: %s\n", what.c_str());
    ++Failures;
  }
}

/** Whether something (a file, a folder) is at `path`. */
inline bool Exists(const std::string& path)
{
  struct stat info;
  return ::stat(path.c_str(), &info) == 0;
}

/** The bytes of a file ("" when it cannot be read). */
inline std::string Slurp(const std::string& path)
{
  std::ifstream in(path, std::ios::binary);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

/** Writes `bytes` as the whole file. */
inline void Spit(const std::string& path, const std::string& bytes)
{
  std::ofstream out(path, std::ios::binary | std::ios::trunc);
  out.write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
}

/** The names in a folder ("." and ".." included), to tell what a run left behind. */
inline std::set<std::string> Entries(const std::string& folder)
{
  std::set<std::string> names;
  if (DIR* d = ::opendir(folder.c_str()))
  {
    while (dirent* e = ::readdir(d))
    {
      names.insert(e->d_name);
    }
    ::closedir(d);
  }
  return names;
}
} // namespace fptest

#endif
