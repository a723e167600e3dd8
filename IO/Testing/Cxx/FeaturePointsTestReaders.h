// Helpers of the reader and writer tests (not installed): a printf-style check that counts into
// fptest::Failures, an observer that keeps a reader's errors and warnings, and the test's folder.
#ifndef FeaturePointsTestReaders_h
#define FeaturePointsTestReaders_h

#include "FeaturePointsTestFiles.h"

#include "vtkCommand.h"

#include <cstdio>
#include <string>
#include <vector>

/** Counts a failure and prints the line and the printf-style message when `condition` is false. */
#define FEATUREPOINTS_CHECK(condition, ...)                                                        \
  do                                                                                               \
  {                                                                                                \
    if (!(condition))                                                                              \
    {                                                                                              \
      std::printf("FAILED (line %d): ", __LINE__);                                                 \
      std::printf(__VA_ARGS__);                                                                    \
      std::printf("\n");                                                                           \
      ++fptest::Failures;                                                                          \
    }                                                                                              \
  } while (false)

namespace fptest
{
/** Keeps the errors and warnings of the object it observes instead of printing them. */
class Catcher : public vtkCommand
{
public:
  static Catcher* New() { return new Catcher; }
  void Execute(vtkObject*, unsigned long event, void* data) override
  {
    const std::string text = data ? static_cast<const char*>(data) : "";
    (event == vtkCommand::ErrorEvent ? this->Errors : this->Warnings).push_back(text);
  }
  std::vector<std::string> Errors;
  std::vector<std::string> Warnings;
};

/** The folder a test writes its files in (its first argument). */
inline std::string Folder;

/** A file in that folder. */
inline std::string PathOf(const std::string& name)
{
  return Folder + "/" + name;
}
} // namespace fptest

#endif
