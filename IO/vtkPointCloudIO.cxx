#include "vtkPointCloudIO.h"

#include "vtkCellArray.h"
#include "vtkCellData.h"
#include "vtkCommand.h"
#include "vtkDataArraySelection.h"
#include "vtkDataSetAttributes.h"
#include "vtkDataSetReader.h"
#include "vtkDataSetWriter.h"
#include "vtkErrorCode.h"
#include "vtkExecutive.h"
#include "vtkFeaturePointsVertexCells.h"
#include "vtkFieldData.h"
#include "vtkObjectFactory.h"
#include "vtkOutputWindow.h"
#include "vtkPointCloudLASReader.h"
#include "vtkPointCloudPCDReader.h"
#include "vtkPointCloudPCDWriter.h"
#include "vtkPointCloudPLYReader.h"
#include "vtkPointCloudPLYWriter.h"
#include "vtkPointCloudTextReader.h"
#include "vtkPointCloudTextWriter.h"
#include "vtkPointData.h"
#include "vtkPointSet.h"
#include "vtkPolyData.h"
#include "vtkPolyDataWriter.h"
#include "vtkStringArray.h"
#include "vtkXMLPolyDataReader.h"
#include "vtkXMLPolyDataWriter.h"
#include "vtkXMLUnstructuredGridReader.h"

#include <vtksys/SystemTools.hxx>

#include <algorithm>
#include <atomic>
#include <cctype>
#include <charconv>
#include <cerrno>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fcntl.h>
#include <fstream>
#include <functional>
#include <limits>
#include <map>
#include <memory>
#include <mutex>
#include <new>
#include <random>
#include <stdexcept>
#include <csignal>
#include <set>
#include <sstream>
// POSIX where vtksys has no counterpart: the isolated reader (fork, memfd_create, prctl, setrlimit,
// alarm, waitpid), the exclusive creation of temporary files (open with O_EXCL), the one stat()
// that tells a file's type and size, and the async-signal-safe removal of temporary files (unlink).
#include <sys/mman.h>
#include <sys/prctl.h>
#include <sys/resource.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>
#include <vector>

// An address sanitizer reserves terabytes of address space: no address space limit under it.
#if defined(__SANITIZE_ADDRESS__)
#define FEATUREPOINTS_IO_SANITIZED 1
#elif defined(__has_feature)
#if __has_feature(address_sanitizer)
#define FEATUREPOINTS_IO_SANITIZED 1
#endif
#endif

vtkStandardNewMacro(vtkPointCloudIO);

namespace
{
const char* const ReadableExtensions[] = { "ply", "vtp", "vtu", "vtk", "pts", "xyz", "txt", "csv",
  "pcd", "las" };
const char* const WritableExtensions[] = { "vtp", "vtk", "ply", "csv", "pcd" };
// Known but not readable in this build: Read() says why in its one line.
const char* const RecognizedExtensions[] = { "laz" };

// Keeps the first message in `first`, except an executive's report that an algorithm failed (a
// dump of the pipeline request, which says nothing of the cause): that one only when nothing else
// comes, shortened to its first sentence.
void KeepFirst(std::string& first, std::string& pipeline, const char* vtkMessage)
{
  std::string text = vtkPointCloudIO::MessageText(vtkMessage);
  const size_t dump = text.find(" returned failure for request");
  const size_t noOutput = text.find(" did not create output for port");
  if (dump != std::string::npos || noOutput != std::string::npos)
  {
    if (pipeline.empty())
    {
      // "Algorithm vtkPolyDataReader(0x...) returned failure ...": the reader failed without a
      // word of its own; its class, without the address, and the usual causes.
      std::string algorithm = text.substr(0, std::min(dump, noOutput));
      const size_t open = algorithm.find("(0x");
      if (open != std::string::npos)
      {
        algorithm.erase(open, algorithm.find(')', open) + 1 - open);
      }
      while (!algorithm.empty() && algorithm.back() == ' ')
      {
        algorithm.pop_back(); // "vtkPolyDataReader (0x...)" in later VTK versions
      }
      const size_t name = algorithm.rfind(' ');
      pipeline = "VTK's " + algorithm.substr(name == std::string::npos ? 0 : name + 1) +
        " failed without saying why (a malformed or cut file, or counts that declare more than "
        "the file holds or memory allows)";
    }
    return;
  }
  if (first.empty())
  {
    first = text;
  }
}

// Keeps the first error an algorithm reports (the observer also keeps it off the console: the
// caller reports it, once, as one line). `First`, when set, receives the message instead (shared
// with a Capture, so that it holds whichever came first).
class ErrorCatcher : public vtkCommand
{
public:
  static ErrorCatcher* New() { return new ErrorCatcher; }
  void Execute(vtkObject*, unsigned long, void* callData) override
  {
    KeepFirst(this->First ? *this->First : this->Message,
      this->Pipeline ? *this->Pipeline : this->PipelineMessage,
      static_cast<const char*>(callData));
  }
  std::string Message, PipelineMessage;
  std::string* First = nullptr;
  std::string* Pipeline = nullptr;
};

// What one read or write keeps of the VTK messages that reach the output window (those of
// objects without an error observer: a reader's internal parser, array or executive): the first
// error, and the first warning when warnings count as failures (the legacy reader reports a short
// or malformed body only as a warning).
struct Capture
{
  std::string Message, PipelineMessage;
  bool WarningsFail = false;
  // A writer writes a temporary file beside the target: the warnings passed on name the target.
  std::string Temporary, Target;
  std::string Passed(const char* text) const
  {
    std::string passed = text ? text : "";
    for (size_t at = 0; !this->Temporary.empty() &&
         (at = passed.find(this->Temporary, at)) != std::string::npos;
         at += this->Target.size())
    {
      passed.replace(at, this->Temporary.size(), this->Target);
    }
    return passed;
  }
  // The message to report: the first, else the executive's.
  const std::string& Text() const
  {
    return this->Message.empty() ? this->PipelineMessage : this->Message;
  }
  void Keep(const char* text) { KeepFirst(this->Message, this->PipelineMessage, text); }
};

// The capture of the read or write running in this thread, if any.
thread_local Capture* CurrentCapture = nullptr;

// VTK has one output window for the process. While any read or write runs, this one is it: it
// hands each message to the capture of the thread that sent it, and the messages of threads
// without a capture (and the warnings a capture does not keep) to the window it replaced. Reads
// and writes in several threads at once each get their own messages.
class CapturingOutputWindow : public vtkOutputWindow
{
public:
  static CapturingOutputWindow* New();
  vtkTypeMacro(CapturingOutputWindow, vtkOutputWindow);
  void DisplayText(const char* text) override
  {
    if (CurrentCapture)
    {
      CurrentCapture->Keep(text);
    }
    else if (this->Previous)
    {
      this->Previous->DisplayText(text);
    }
  }
  void DisplayErrorText(const char* text) override
  {
    if (CurrentCapture)
    {
      CurrentCapture->Keep(text);
    }
    else if (this->Previous)
    {
      this->Previous->DisplayErrorText(text);
    }
  }
  void DisplayWarningText(const char* text) override
  {
    if (CurrentCapture && CurrentCapture->WarningsFail)
    {
      CurrentCapture->Keep(text);
    }
    else if (this->Previous)
    {
      this->Previous->DisplayWarningText(
        CurrentCapture ? CurrentCapture->Passed(text).c_str() : text);
    }
  }
  void DisplayGenericWarningText(const char* text) override { this->DisplayWarningText(text); }
  void DisplayDebugText(const char*) override {}
  vtkSmartPointer<vtkOutputWindow> Previous;
};
vtkStandardNewMacro(CapturingOutputWindow);

// The installed window and how many captures use it (guarded by CaptureMutex).
std::mutex CaptureMutex;
int CaptureUsers = 0;
vtkSmartPointer<CapturingOutputWindow> CaptureWindow;

// Captures this thread's messages for the lifetime of the scope, whatever way it is left.
struct ScopedCapture
{
  explicit ScopedCapture(bool warningsFail)
    : Outer(CurrentCapture)
  {
    this->Window->WarningsFail = warningsFail;
    CurrentCapture = this->Window.get();
    std::lock_guard<std::mutex> lock(CaptureMutex);
    if (CaptureUsers++ == 0)
    {
      CaptureWindow = vtkSmartPointer<CapturingOutputWindow>::New();
      CaptureWindow->Previous = vtkOutputWindow::GetInstance();
      vtkOutputWindow::SetInstance(CaptureWindow);
    }
  }
  ~ScopedCapture()
  {
    CurrentCapture = this->Outer;
    std::lock_guard<std::mutex> lock(CaptureMutex);
    if (--CaptureUsers == 0)
    {
      if (vtkOutputWindow::GetInstance() == CaptureWindow)
      {
        vtkOutputWindow::SetInstance(CaptureWindow->Previous);
      }
      CaptureWindow = nullptr;
    }
  }
  ScopedCapture(const ScopedCapture&) = delete;
  void operator=(const ScopedCapture&) = delete;
  std::unique_ptr<Capture> Window{ new Capture };
  Capture* Outer;
};

// What an exception thrown out of a reader or writer says, as one line.
std::string ExceptionText(const std::exception& e)
{
  if (dynamic_cast<const std::bad_alloc*>(&e) || dynamic_cast<const std::length_error*>(&e))
  {
    return "not enough memory";
  }
  return std::string("unexpected failure (") + e.what() + ")";
}

std::string WithFile(const std::string& fileName, const std::string& message)
{
  // Our readers' messages already start with the file name.
  if (message.compare(0, fileName.size(), fileName) == 0)
  {
    return message;
  }
  return fileName + ": " + message;
}

std::string Join(const char* const* begin, const char* const* end)
{
  std::string out;
  for (auto it = begin; it != end; ++it)
  {
    out += (out.empty() ? "" : ", ") + std::string(".") + *it;
  }
  return out;
}

// A polydata view of any point set: the same points and point data, one vertex per point when
// the input has no cells to show.
vtkSmartPointer<vtkPolyData> AsPolyData(vtkPointSet* data)
{
  if (auto poly = vtkPolyData::SafeDownCast(data))
  {
    return poly;
  }
  auto poly = vtkSmartPointer<vtkPolyData>::New();
  poly->SetPoints(data->GetPoints());
  poly->GetPointData()->ShallowCopy(data->GetPointData());
  poly->SetVerts(vtkPointCloudIO::MakeVertexCells(data->GetNumberOfPoints()));
  return poly;
}

// An array name as an XML attribute value: VTK 9.1's XML writers write names as they are, so
// that a quote, '<' or '&' in a name (from a CSV header, say) makes the file unreadable, and an
// empty name is refused when read back. Entities are decoded by the reader: the name comes back
// as it was; an empty one comes back as "unnamed" (as the PLY and PCD writers name it).
// An array name as valid UTF-8 (a byte that starts no valid sequence, as from a Windows-1252
// header, is taken as Latin-1: 0xE9 is 'é') with control characters other than tab, newline and
// carriage return as '_', cut so that its `cost` (bytes as the file stores them) stays within
// 240: VTK's readers keep names in 256-byte buffers ("Unsupported data type" beyond), and a
// suffix "_2", ... may follow. An empty name is "unnamed".
std::string FitName(const char* name, const std::function<size_t(const std::string&)>& cost)
{
  if (!name || !*name)
  {
    return "unnamed";
  }
  std::string out;
  size_t spent = 0;
  const auto* c = reinterpret_cast<const unsigned char*>(name);
  while (*c)
  {
    // The next character, as UTF-8.
    std::string ch;
    int length = *c < 0x80 ? 1 : (*c >> 5) == 6 ? 2 : (*c >> 4) == 14 ? 3 : (*c >> 3) == 30 ? 4 : 0;
    for (int k = 1; k < length; ++k)
    {
      length = (c[k] & 0xC0) == 0x80 ? length : 0;
    }
    if (length == 0)
    {
      ch = { static_cast<char>(0xC0 | (*c >> 6)), static_cast<char>(0x80 | (*c & 0x3F)) };
      length = 1;
    }
    else if (*c < 0x20 && *c != '\t' && *c != '\n' && *c != '\r')
    {
      ch = "_";
    }
    else
    {
      ch.assign(reinterpret_cast<const char*>(c), static_cast<size_t>(length));
    }
    const size_t more = cost(ch);
    if (spent + more > 240)
    {
      break;
    }
    spent += more;
    out += ch;
    c += length;
  }
  return out;
}

// An array name for VTK's XML writers (VTK 9.1 writes names as they are): FitName(), then
// quotes, '<', '>', '&' and apostrophes as XML entities (the XML readers give them back).
std::string XMLName(const char* name)
{
  const std::string fitted = FitName(name, [](const std::string& ch) { return ch.size(); });
  std::string out;
  for (const char c : fitted)
  {
    switch (c)
    {
      case '&': out += "&amp;"; break;
      case '<': out += "&lt;"; break;
      case '>': out += "&gt;"; break;
      case '"': out += "&quot;"; break;
      case '\'': out += "&apos;"; break;
      default: out += c;
    }
  }
  return out;
}

// An array name for VTK's legacy writer, which writes a byte other than a letter, a digit and
// a few marks as "%XX" (three bytes in the file): FitName() at that cost.
std::string LegacyName(const char* name)
{
  return FitName(name, [](const std::string& ch) {
    size_t bytes = 0;
    for (const char c : ch)
    {
      bytes += std::isalnum(static_cast<unsigned char>(c)) || c == '_' || c == '-' || c == '.' ? 1 : 3;
    }
    return bytes;
  });
}


// The temporary files that a signal handler removes (RemoveTemporaryFileInProgress): one slot
// per file being written, so that writers in several threads each keep theirs. A slot is
// claimed (Claimed), then holds a name (Named) until released (Free); a handler reads only the
// named ones. The name is stored before the file is created, so a signal that comes between the
// two, to any thread, never leaves the file behind.
enum SlotState : int
{
  Free = 0,
  Claimed = 1,
  Named = 2,
};
struct TemporarySlot
{
  std::atomic<int> State{ Free };
  char Name[4096];
};
static_assert(std::atomic<int>::is_always_lock_free, "a signal handler reads the slots");
TemporarySlot TemporarySlots[16];

// Claims a slot and stores `name` in it; -1 when every slot is taken or the name is too long.
int RegisterTemporary(const std::string& name)
{
  if (name.size() >= sizeof(TemporarySlots[0].Name))
  {
    return -1;
  }
  for (int s = 0; s < static_cast<int>(sizeof(TemporarySlots) / sizeof(TemporarySlots[0])); ++s)
  {
    int expected = Free;
    if (TemporarySlots[s].State.compare_exchange_strong(expected, Claimed))
    {
      std::memcpy(TemporarySlots[s].Name, name.c_str(), name.size() + 1);
      TemporarySlots[s].State.store(Named);
      return s;
    }
  }
  return -1;
}

void ReleaseTemporary(int slot)
{
  if (slot >= 0)
  {
    TemporarySlots[slot].State.store(Free);
  }
}

// A name for a temporary file beside the target: ".BASE.XXXXXX" in the target's folder, with
// six random letters or digits (as mkstemp makes them).
std::string TemporaryName(const std::string& prefix)
{
  static const char letters[] = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789";
  thread_local std::mt19937_64 random(std::random_device{}());
  std::string name = prefix;
  for (int i = 0; i < 6; ++i)
  {
    name += letters[random() % (sizeof(letters) - 1)];
  }
  return name;
}

// The value of attribute `name` in the XML tag text `tag` ("" when absent): any whitespace
// before the name, either quote.
std::string TagAttribute(const std::string& tag, const std::string& name)
{
  // The tag's name, then attributes name = "value" (either quote; spaces around '='): a name is
  // only ever matched as an attribute's name, never inside another attribute's value.
  auto space = [](char c) { return std::isspace(static_cast<unsigned char>(c)) != 0; };
  size_t at = tag.find_first_of(" \t\r\n");
  while (at < tag.size())
  {
    while (at < tag.size() && space(tag[at]))
    {
      ++at;
    }
    const size_t nameStart = at;
    while (at < tag.size() && !space(tag[at]) && tag[at] != '=')
    {
      ++at;
    }
    const std::string attribute = tag.substr(nameStart, at - nameStart);
    while (at < tag.size() && space(tag[at]))
    {
      ++at;
    }
    if (at >= tag.size() || tag[at] != '=')
    {
      continue; // a name without a value: none of ours
    }
    ++at;
    while (at < tag.size() && space(tag[at]))
    {
      ++at;
    }
    if (at >= tag.size() || (tag[at] != '"' && tag[at] != '\''))
    {
      return std::string();
    }
    const char quote = tag[at];
    const size_t end = tag.find(quote, at + 1);
    if (end == std::string::npos)
    {
      return std::string();
    }
    if (attribute == name)
    {
      return tag.substr(at + 1, end - at - 1);
    }
    at = end + 1;
  }
  return std::string();
}

// An appended array's offset as VTK's reader reads it (a stream extraction): spaces around it and
// a leading '+' allowed. False for anything else: a sign, a fraction, an exponent, other text.
bool ParseOffset(const std::string& text, uint64_t& offset)
{
  size_t first = 0, last = text.size();
  while (first < last && std::isspace(static_cast<unsigned char>(text[first])))
  {
    ++first;
  }
  while (last > first && std::isspace(static_cast<unsigned char>(text[last - 1])))
  {
    --last;
  }
  if (first < last && text[first] == '+')
  {
    ++first;
  }
  const auto parsed = std::from_chars(text.data() + first, text.data() + last, offset);
  return first < last && parsed.ec == std::errc() && parsed.ptr == text.data() + last;
}

// `text` in capitals: VTK's legacy reader takes its keywords and types in any case.
std::string UpperCase(std::string text)
{
  std::transform(text.begin(), text.end(), text.begin(),
    [](unsigned char c) { return static_cast<char>(std::toupper(c)); });
  return text;
}

// `word` as a whole number of 0 or more, as VTK's reader takes a count or an id (a leading '+'
// passes).
bool WholeNumber(const std::string& word, long long& value)
{
  const char* first = word.data() + (word.size() > 1 && word[0] == '+' ? 1 : 0);
  const char* end = word.data() + word.size();
  const auto parsed = std::from_chars(first, end, value);
  return parsed.ec == std::errc() && parsed.ptr == end && value >= 0;
}

// A legacy VTK file's POINTS line against the file's size: a count that is not a whole number of
// 0 or more (VTK's reader then reads the count as a keyword, "Unrecognized keyword: 0"), or more
// points than the file's bytes can hold (VTK's reader allocates them all before it finds the file
// short). The line is the data set's: `POINTS n type` after the DATASET line, before any FIELD
// data (whose arrays, and strings in them, may hold such a line too; a file with field data there
// is left to VTK's reader, under the memory limit of ReadIsolated), in the file's first 64 KiB.
bool CheckLegacyPoints(const std::string& fileName, double fileSize, std::string& error)
{
  std::ifstream file(fileName, std::ios::binary);
  std::string head(size_t(64) << 10, '\0');
  file.read(&head[0], static_cast<std::streamsize>(head.size()));
  head.resize(static_cast<size_t>(file.gcount()));
  std::istringstream in(head);
  std::string line;
  bool binary = false, dataset = false;
  static const std::set<std::string> types = { "BIT", "CHAR", "UNSIGNED_CHAR", "SHORT",
    "UNSIGNED_SHORT", "INT", "UNSIGNED_INT", "LONG", "UNSIGNED_LONG", "VTKTYPEINT64",
    "VTKTYPEUINT64", "FLOAT", "DOUBLE" };
  for (int number = 1; std::getline(in, line); ++number)
  {
    std::istringstream words(line);
    std::vector<std::string> word;
    for (std::string w; words >> w;)
    {
      word.push_back(w);
    }
    const std::string keyword = word.empty() ? std::string() : UpperCase(word[0]);
    const size_t version = line.find("DataFile Version");
    if (number == 1 && version != std::string::npos)
    {
      // VTK 9.1's reader reads versions up to 5.1; it refuses a newer one ("Reading file
      // version: 6.0 with older reader version 5.1") or crashes (7 and beyond).
      std::istringstream text(line.substr(version + 16));
      std::string declared;
      text >> declared;
      long long major = 0, minor = 0;
      const size_t dot = declared.find('.');
      const bool parsed = WholeNumber(declared.substr(0, dot), major) &&
        (dot == std::string::npos || WholeNumber(declared.substr(dot + 1), minor));
      if (parsed && (major > 5 || (major == 5 && minor > 1)))
      {
        error = fileName + ":1: the header declares file version " +
          vtkPointCloudIO::MessageText(declared.substr(0, 40).c_str()) +
          ", newer than VTK's legacy reader reads (at most 5.1): a corrupt header, or a file "
          "written by a newer VTK";
        return false;
      }
    }
    if (number == 3)
    {
      binary = keyword == "BINARY";
    }
    if (number < 4)
    {
      continue;
    }
    dataset = dataset || keyword == "DATASET";
    if (!dataset)
    {
      continue;
    }
    if (keyword == "FIELD" || keyword == "POINT_DATA" || keyword == "CELL_DATA")
    {
      return true; // data follows whose bytes this check does not read
    }
    if (keyword != "POINTS" || word.size() != 3 || !types.count(UpperCase(word[2])))
    {
      continue;
    }
    // VTK reads the count with a stream extraction: a leading '+' and leading zeros pass.
    std::string count = word[1];
    size_t first = count[0] == '+' ? 1 : 0;
    const bool digits = first < count.size() &&
      std::all_of(count.begin() + first, count.end(), [](unsigned char c) { return std::isdigit(c); });
    while (digits && first + 1 < count.size() && count[first] == '0')
    {
      ++first;
    }
    if (!digits || count.size() - first > 19)
    {
      error = fileName + ":" + std::to_string(number) + ": the POINTS line declares '" + count +
        "' points, not a whole number of 0 or more";
      return false;
    }
    const double points = std::stod(count.substr(first));
    // At least 3 bytes a number in ASCII (a digit and a separator, 3 numbers a point: 6 bytes a
    // point); 4 bytes a number in binary (float, the smallest type VTK writes for points).
    const double least = points * (binary ? 12.0 : 6.0);
    if (least > fileSize)
    {
      error = fileName + ":" + std::to_string(number) + ": the POINTS line declares " + count +
        " points, more than the file's " + std::to_string(static_cast<long long>(fileSize)) +
        " bytes can hold (a file cut short, or a corrupt count)";
      return false;
    }
    return true;
  }
  return true;
}

// Why VTK's XML reader failed to decompress a file's data, where it says "Zlib error while
// uncompressing data" whatever the compressor (VTK's LZ4 and LZMA compressors print zlib's text)
// or only "Unknown error": the compressor the file declares, read from its VTKFile element. Empty
// when the message is of another kind or the file declares no compressor.
std::string XMLCompressionProblem(const std::string& fileName, const std::string& message)
{
  if (message.find("uncompressing") == std::string::npos && message != "Unknown error." &&
    message != "Unknown error")
  {
    return {};
  }
  std::ifstream file(fileName, std::ios::binary);
  std::string head(4096, '\0');
  file.read(&head[0], static_cast<std::streamsize>(head.size()));
  head.resize(static_cast<size_t>(std::max<std::streamsize>(file.gcount(), 0)));
  const size_t element = head.find("<VTKFile");
  const size_t attribute = element == std::string::npos ? element : head.find("compressor=\"", element);
  const size_t close = attribute == std::string::npos ? attribute : head.find('"', attribute + 12);
  if (close == std::string::npos || head.find('>', element) < attribute)
  {
    return {};
  }
  const std::string compressor = head.substr(attribute + 12, close - attribute - 12);
  return fileName + ": cannot read: its data do not decompress with " +
    vtkPointCloudIO::MessageText(compressor.c_str()) +
    ", the compressor it declares (corrupt or cut data, or data compressed otherwise)";
}

// Why VTK's XML reader read no point, or failed on the Points array ("Cannot read points array
// from Points in piece 0"), in words: a Points array of a type that holds no numbers (VTK reads
// a String array as no point at all), or an ASCII Points array with a word where a coordinate
// should be (VTK says the array "may be too short"). Empty when neither is found (VTK's message
// or the caller's then stands). Reads at most the first 64 MB.
std::string XMLPointsProblem(const std::string& fileName)
{
  std::ifstream file(fileName, std::ios::binary | std::ios::ate);
  const std::streamoff size = file ? static_cast<std::streamoff>(file.tellg()) : 0;
  file.seekg(0);
  std::string text(static_cast<size_t>(std::min<std::streamoff>(
                     std::max<std::streamoff>(size, 0), std::streamoff(64) << 20)),
    '\0');
  file.read(&text[0], static_cast<std::streamsize>(text.size()));
  text.resize(static_cast<size_t>(std::max<std::streamsize>(file.gcount(), 0)));
  const size_t points = text.find("<Points");
  const size_t array = points == std::string::npos ? points : text.find("<DataArray", points);
  const size_t end = array == std::string::npos ? array : text.find('>', array);
  if (end == std::string::npos)
  {
    return {};
  }
  const std::string tag = text.substr(array, end - array);
  auto attribute = [&tag](const char* name) {
    const std::string key = std::string(" ") + name + "=\"";
    const size_t at = tag.find(key);
    const size_t close = at == std::string::npos ? at : tag.find('"', at + key.size());
    return close == std::string::npos ? std::string()
                                      : tag.substr(at + key.size(), close - at - key.size());
  };
  const std::string type = attribute("type");
  static const char* const numeric[] = { "Int8", "UInt8", "Int16", "UInt16", "Int32", "UInt32",
    "Int64", "UInt64", "Float32", "Float64" };
  if (!type.empty() &&
    std::find_if(std::begin(numeric), std::end(numeric),
      [&type](const char* t) { return type == t; }) == std::end(numeric))
  {
    return fileName + ": cannot read: its Points array is of type " +
      vtkPointCloudIO::MessageText(type.c_str()) +
      ", which holds no coordinates (Float32, Float64 or an integer type)";
  }
  if (attribute("format") != "ascii" || tag.back() == '/')
  {
    return {};
  }
  // The values up to the array's end tag: the first that is no number.
  const size_t close = text.find('<', end);
  std::istringstream values(text.substr(end + 1, close == std::string::npos ? std::string::npos
                                                                           : close - end - 1));
  long long index = 0;
  for (std::string word; values >> word; ++index)
  {
    double value = 0.0;
    const char* first = word.data() + (word.size() > 1 && word[0] == '+' ? 1 : 0);
    const auto parsed = std::from_chars(first, word.data() + word.size(), value);
    if (parsed.ec != std::errc() || parsed.ptr != word.data() + word.size())
    {
      if (word.size() > 40)
      {
        word = word.substr(0, 40) + "...";
      }
      return fileName + ": cannot read: its ASCII Points array holds '" +
        vtkPointCloudIO::MessageText(word.c_str()) + "' as value " + std::to_string(index) +
        " (point " + std::to_string(index / 3) + ", counting from 0), not a number";
    }
  }
  return {};
}

// Why VTK's legacy reader failed on an ASCII file, where it says only "Error reading ascii
// data": the first coordinate of the data set's POINTS that is no finite number (a "nan", an
// "inf", a word), the end of the file before the declared count, or a number after the declared
// count (VTK then reads it as a keyword: "Unrecognized keyword: 0"). Empty when the file is not
// ASCII or nothing of that kind is found (VTK's message then stands).
std::string LegacyPointsProblem(const std::string& fileName)
{
  std::ifstream file(fileName, std::ios::binary);
  std::string line;
  long number = 0;
  bool dataset = false;
  long long count = -1;
  std::string pointsType; // the POINTS line's type
  while (count < 0 && std::getline(file, line))
  {
    ++number;
    std::istringstream words(line);
    std::string keyword, declared;
    words >> keyword >> declared >> pointsType;
    keyword = UpperCase(keyword);
    if (number == 3 && keyword != "ASCII")
    {
      return {};
    }
    dataset = dataset || (number >= 4 && keyword == "DATASET");
    if (dataset && (keyword == "FIELD" || keyword == "POINT_DATA" || keyword == "CELL_DATA"))
    {
      return {}; // field data first, whose arrays may hold a line like a POINTS line (see
                 // CheckLegacyPoints): VTK's message stands
    }
    if (dataset && keyword == "POINTS")
    {
      const auto parsed = std::from_chars(declared.data(), declared.data() + declared.size(), count);
      if (parsed.ec != std::errc() || count < 0)
      {
        return {};
      }
    }
  }
  const long long values = 3 * std::max(count, 0LL);
  long long read = 0;
  // A number where the section after the points should start.
  auto isNumber = [](const std::string& word) {
    double value = 0.0;
    const char* end = word.data() + word.size();
    const auto parsed = std::from_chars(word.data() + (word[0] == '+' ? 1 : 0), end, value);
    return parsed.ec == std::errc() && parsed.ptr == end;
  };
  std::string lowerType = pointsType;
  std::transform(lowerType.begin(), lowerType.end(), lowerType.begin(),
    [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  const bool integerPoints = !lowerType.empty() && lowerType.compare(0, 5, "float") != 0 &&
    lowerType.compare(0, 6, "double") != 0;
  // VTK's reader matches a type by its first letters.
  static const char* const known[] = { "bit", "unsigned_char", "char", "unsigned_short", "short",
    "unsigned_int", "int", "unsigned_long", "long", "float", "double", "vtkidtype",
    "vtktypeint64", "vtktypeuint64" };
  if (count >= 0 && std::none_of(std::begin(known), std::end(known), [&lowerType](const char* t) {
        return lowerType.compare(0, std::strlen(t), t) == 0;
      }))
  {
    // VTK's reader says "Unsupported data type: bogus".
    return fileName + ":" + std::to_string(number) + ": the POINTS line names the type '" +
      vtkPointCloudIO::MessageText(pointsType.substr(0, 20).c_str()) +
      "', no numeric type of the legacy format (bit, unsigned_char, char, unsigned_short, short, "
      "unsigned_int, int, unsigned_long, long, float, double, vtkIdType, vtktypeint64, "
      "vtktypeuint64)";
  }
  const std::string tooMany = ": the POINTS block holds more than " + std::to_string(count) +
    " x 3 values (a wrong POINTS count)";
  while (read < values && std::getline(file, line))
  {
    ++number;
    std::istringstream words(line);
    std::string extra;
    for (std::string word; read < values && words >> word; ++read)
    {
      double value = 0.0;
      const char* end = word.data() + word.size();
      const auto parsed = std::from_chars(word.data() + (word[0] == '+' ? 1 : 0), end, value);
      if (parsed.ec != std::errc() || parsed.ptr != end || !std::isfinite(value))
      {
        return fileName + ":" + std::to_string(number) + ": coordinate " +
          std::to_string(read % 3 + 1) + " of point " + std::to_string(read / 3 + 1) + " ('" +
          (word.size() > 40 ? word.substr(0, 40) + "..." : word) + "') is not a finite number";
      }
      if (integerPoints && value != std::floor(value))
      {
        // VTK's reader says only "Error reading ascii data".
        return fileName + ":" + std::to_string(number) + ": coordinate " +
          std::to_string(read % 3 + 1) + " of point " + std::to_string(read / 3 + 1) + " ('" +
          (word.size() > 40 ? word.substr(0, 40) + "..." : word) +
          "') is not a whole number, as the POINTS line's type '" +
          vtkPointCloudIO::MessageText(pointsType.substr(0, 20).c_str()) + "' needs";
      }
    }
    if (read == values && words >> extra && isNumber(extra))
    {
      return fileName + ":" + std::to_string(number) + tooMany;
    }
  }
  if (count > 0 && read < values)
  {
    return fileName + ": the POINTS line declares " + std::to_string(count) +
      " points; the file ends after " + std::to_string(read / 3) + " of them";
  }
  // The rest (cells, point and cell data): the first value that is no number, on a line that is
  // not a section's or an array's header. A string array's values are words: nothing is said
  // past its header.
  static const std::set<std::string> keywords = { "POINT_DATA", "CELL_DATA", "SCALARS",
    "LOOKUP_TABLE", "VECTORS", "NORMALS", "TEXTURE_COORDINATES", "TENSORS", "FIELD",
    "COLOR_SCALARS", "METADATA", "INFORMATION", "NAME", "DATA", "VERTICES", "LINES", "POLYGONS",
    "TRIANGLE_STRIPS", "CELLS", "CELL_TYPES", "OFFSETS", "CONNECTIVITY", "GLOBAL_IDS",
    "PEDIGREE_IDS", "EDGE_FLAGS" };
  static const std::set<std::string> types = { "bit", "unsigned_char", "char", "unsigned_short",
    "short", "unsigned_int", "int", "unsigned_long", "long", "float", "double", "vtkIdType",
    "vtktypeint64", "vtktypeuint64", "string", "utf8_string", "variant" };
  bool first = count >= 0; // the first line after the points
  while (std::getline(file, line))
  {
    ++number;
    std::istringstream words(line);
    std::vector<std::string> all;
    for (std::string word; words >> word;)
    {
      all.push_back(word);
    }
    if (all.empty())
    {
      continue;
    }
    if (first && isNumber(all[0]))
    {
      return fileName + ":" + std::to_string(number) + tooMany;
    }
    first = false;
    const bool header = keywords.count(all[0]) > 0 || (all.size() == 4 && types.count(all[3]));
    if (header)
    {
      if (std::find(all.begin(), all.end(), "string") != all.end() ||
        std::find(all.begin(), all.end(), "utf8_string") != all.end() ||
        std::find(all.begin(), all.end(), "variant") != all.end())
      {
        return {};
      }
      continue;
    }
    for (size_t w = 0; w < all.size(); ++w)
    {
      const std::string& word = all[w];
      double value = 0.0;
      const char* end = word.data() + word.size();
      const auto parsed = std::from_chars(word.data() + (word[0] == '+' ? 1 : 0), end, value);
      if (parsed.ec != std::errc() || parsed.ptr != end || !std::isfinite(value))
      {
        return fileName + ":" + std::to_string(number) + ": value " + std::to_string(w + 1) +
          " of the line ('" + (word.size() > 40 ? word.substr(0, 40) + "..." : word) +
          "') is not a finite number, which VTK's legacy reader cannot read";
      }
    }
  }
  return {};
}

// The words of an ASCII legacy VTK file after its three header lines, one after the other with the
// line each is on: VTK's reader reads values across lines (a stream extraction).
class LegacyWords
{
public:
  explicit LegacyWords(const std::string& fileName)
    : File(fileName, std::ios::binary)
  {
  }
  // The header lines: the version (Version), and false when the file is not ASCII.
  bool Ascii()
  {
    std::string format;
    for (int header = 0; header < 3; ++header)
    {
      if (!std::getline(this->File, this->Text))
      {
        return false;
      }
      ++this->Number;
      const size_t at = this->Text.find("Version");
      if (header == 0 && at != std::string::npos)
      {
        this->Version = std::atof(this->Text.c_str() + at + 7);
      }
    }
    std::istringstream words(this->Text);
    words >> format;
    this->Text.clear();
    return UpperCase(format) == "ASCII";
  }
  // The next word; false at the end of the file.
  bool Next(std::string& word)
  {
    auto space = [](char c) { return std::isspace(static_cast<unsigned char>(c)) != 0; };
    for (;;)
    {
      while (this->At < this->Text.size() && space(this->Text[this->At]))
      {
        ++this->At;
      }
      if (this->At < this->Text.size())
      {
        const size_t start = this->At;
        while (this->At < this->Text.size() && !space(this->Text[this->At]))
        {
          ++this->At;
        }
        word.assign(this->Text, start, this->At - start);
        return true;
      }
      if (!std::getline(this->File, this->Text))
      {
        return false;
      }
      ++this->Number;
      this->At = 0;
    }
  }
  // Skips a METADATA block (its keyword just read): its lines up to an empty one.
  void SkipMetadata()
  {
    while (std::getline(this->File, this->Text))
    {
      ++this->Number;
      if (this->Text.empty() || this->Text == "\r")
      {
        break;
      }
    }
    this->Text.clear();
    this->At = 0;
  }
  // The line of the word last read.
  long Line() const { return this->Number; }
  double Version = 0.0; // the file format's version (cells as offsets from 5 on)

private:
  std::ifstream File;
  std::string Text;
  size_t At = 0;
  long Number = 0;
};

// A word of a file quoted for a message (cut to 40 bytes).
std::string QuotedWord(const std::string& word)
{
  const std::string shown = word.size() > 40 ? word.substr(0, 40) + "..." : word;
  return "'" + vtkPointCloudIO::MessageText(shown.c_str()) + "'";
}

// One block of ASCII cells, as a legacy file declares it on its line (VERTICES, LINES, POLYGONS,
// TRIANGLE_STRIPS, CELLS), against what the block holds: before version 5 `n size`, then n cells
// of a count and that many point ids (size values in all); from version 5 on `offsets
// connectivity`, then an OFFSETS line and that many offsets (from 0, never decreasing, the last
// the connectivity's size), a CONNECTIVITY line and that many point ids. Each id is a point of the
// POINTS line's `points`. Sets `cells` to the block's cells; the problem, or "".
std::string LegacyCellBlockProblem(LegacyWords& in, const std::string& fileName,
  const std::string& keyword, bool offsets, long long points, long long& cells)
{
  const long line = in.Line();
  const std::string where = "the " + keyword + " block (line " + std::to_string(line) + ")";
  std::string first, second, word;
  long long n = 0, size = 0;
  if (!in.Next(first) || !in.Next(second))
  {
    return {};
  }
  const bool firstWhole = WholeNumber(first, n);
  if (!firstWhole || !WholeNumber(second, size))
  {
    return fileName + ":" + std::to_string(line) + ": the " + keyword + " line declares " +
      (firstWhole ? QuotedWord(second) + (offsets ? " connectivity values" : " values")
                  : QuotedWord(first) + (offsets ? " offsets" : " cells")) +
      ", not a whole number of 0 or more";
  }
  const std::string at = fileName + ":";
  // The next word as a point id; `which` names it ("in cell 3", "as connectivity value 7").
  auto pointId = [&](const std::string& which) -> std::string {
    long long id = 0;
    if (!in.Next(word))
    {
      return fileName + ": " + where + " declares " +
        std::to_string(offsets ? size : n) + (offsets ? " connectivity values" : " cells") +
        "; the file ends before the point id " + which;
    }
    if (!WholeNumber(word, id) || id >= points)
    {
      return at + std::to_string(in.Line()) + ": " + QuotedWord(word) + " " + which +
        " (counting from 0) of " + where + " is not a point id from 0 to " +
        std::to_string(points - 1) +
        " (the block holds fewer values than its line declares, or a corrupt value)";
    }
    return {};
  };
  // The next word as item v of the block's n (a cell's number of points, an offset).
  auto nextCount = [&](const std::string& item, long long v, long long& value) -> std::string {
    if (!in.Next(word))
    {
      return fileName + ": " + where + " declares " + std::to_string(n) + " " + item +
        "s; the file ends after " + std::to_string(v) + " of them";
    }
    if (!WholeNumber(word, value))
    {
      return at + std::to_string(in.Line()) + ": " + QuotedWord(word) + " where " + item + " " +
        std::to_string(v) + " (counting from 0) of the " + std::to_string(n) + " that " + where +
        " declares should be: the block holds fewer " + item + "s than declared";
    }
    return {};
  };
  if (!offsets)
  {
    long long used = 0;
    for (long long c = 0; c < n; ++c)
    {
      long long k = 0;
      std::string problem = nextCount("cell", c, k);
      if (problem.empty() && k >= size - used) // 1 + k more values pass the size
      {
        problem = at + std::to_string(in.Line()) + ": cell " + std::to_string(c) +
          " (counting from 0) of " + where + " runs past the " + std::to_string(size) +
          " values that its line declares (a corrupt size or point count)";
      }
      if (!problem.empty())
      {
        return problem;
      }
      used += 1 + k;
      for (long long p = 0; p < k; ++p)
      {
        const std::string idProblem = pointId("in cell " + std::to_string(c));
        if (!idProblem.empty())
        {
          return idProblem;
        }
      }
    }
    if (used != size)
    {
      return at + std::to_string(line) + ": the " + keyword + " line declares " +
        std::to_string(n) + " cells in " + std::to_string(size) + " values, but its cells hold " +
        std::to_string(used) + " (a corrupt size)";
    }
    cells = n;
    return {};
  }
  // From version 5 on: the OFFSETS line and its n offsets, the CONNECTIVITY line and its ids.
  for (const std::string part : { "OFFSETS", "CONNECTIVITY" })
  {
    std::string type;
    bool read = in.Next(word);
    while (read && word == "METADATA")
    {
      in.SkipMetadata(); // the offsets' information keys
      read = in.Next(word);
    }
    const long partLine = in.Line();
    if (!read || (word == part && !in.Next(type)))
    {
      return fileName + ": " + where + ": the file ends before its " + part + " line";
    }
    static const std::set<std::string> types = { "unsigned_char", "char", "unsigned_short",
      "short", "unsigned_int", "int", "unsigned_long", "long", "vtkIdType", "vtktypeint64",
      "vtktypeuint64" };
    long long number = 0;
    if (word == part && !types.count(type))
    {
      return at + std::to_string(partLine) + ": the " + part + " line of " + where +
        " names no integer type (" + QuotedWord(type) + " follows it)";
    }
    if (word != part)
    {
      return at + std::to_string(in.Line()) + ": " + QuotedWord(word) + " where the " + part +
        " line of " + where + " should be" +
        (part == "CONNECTIVITY" && WholeNumber(word, number)
            ? ": the block holds more than the " + std::to_string(n) +
              " offsets that its line declares"
            : std::string());
    }
    if (part == "CONNECTIVITY")
    {
      for (long long v = 0; v < size; ++v)
      {
        const std::string problem = pointId("as connectivity value " + std::to_string(v));
        if (!problem.empty())
        {
          return problem;
        }
      }
      break;
    }
    long long previous = 0;
    for (long long v = 0; v < n; ++v)
    {
      long long offset = 0;
      const std::string problem = nextCount("offset", v, offset);
      if (!problem.empty())
      {
        return problem;
      }
      const std::string which = at + std::to_string(in.Line()) + ": offset " +
        std::to_string(v) + " (counting from 0) of " + where + " is " + std::to_string(offset);
      if (v == 0 && offset != 0)
      {
        return which + ", not 0";
      }
      if (offset < previous)
      {
        return which + ", less than the one before it (" + std::to_string(previous) + ")";
      }
      if (v == n - 1 && offset != size)
      {
        return which + ", the last, but its line declares " + std::to_string(size) +
          " connectivity values (a corrupt offset or count)";
      }
      previous = offset;
    }
  }
  cells = n > 0 ? n - 1 : 0;
  return {};
}

// A value as VTK's legacy reader reads one in ASCII (a '+' before it allowed).
bool LegacyNumber(const std::string& word)
{
  double value = 0.0;
  const char* first = word.data() + (word.size() > 1 && word[0] == '+' ? 1 : 0);
  const char* end = word.data() + word.size();
  const auto parsed = std::from_chars(first, end, value);
  return parsed.ec == std::errc() && parsed.ptr == end;
}

// The `tuples` x `components` values of an ASCII array after its line (`what`, "the SCALARS
// array 's' (line 8)"; `declared` says where the counts come from): the problem when the file
// ends before them or a word that is no number stands among them (the next section's keyword: an
// array shorter than declared), or "".
std::string LegacyValuesProblem(LegacyWords& in, const std::string& fileName,
  const std::string& what, long long tuples, long long components, const std::string& declared)
{
  const double product = static_cast<double>(tuples) * static_cast<double>(components);
  const long long values = product > 4e18 ? 4000000000000000000LL : tuples * components;
  std::string word;
  for (long long v = 0; v < values; ++v)
  {
    if (!in.Next(word))
    {
      return fileName + ": " + what + " declares " + std::to_string(values) + " values (" +
        declared + "); the file ends after " + std::to_string(v) + " of them";
    }
    if (!LegacyNumber(word))
    {
      return fileName + ":" + std::to_string(in.Line()) + ": " + QuotedWord(word) +
        " where value " + std::to_string(v) + " (counting from 0) of the " +
        std::to_string(values) + " that " + what + " declares (" + declared +
        ") should be: the array holds " + std::to_string(v) + ", fewer than declared";
    }
  }
  return {};
}

// Why VTK's legacy reader failed on an ASCII file's cells or attribute arrays, where it says
// "Error reading ascii cell data!", "Possible mismatch of datasize with declaration",
// "Unrecognized keyword", or nothing, or crashes: the first cell block (see
// LegacyCellBlockProblem), CELL_TYPES block or array of point, cell or field data whose values
// disagree with its line, named with that line, or a number after a block's or an array's last
// value (one that holds more than declared). An array of POINT_DATA n or CELL_DATA n holds n
// times its components' values (SCALARS, VECTORS, NORMALS, TENSORS, TEXTURE_COORDINATES,
// COLOR_SCALARS, GLOBAL_IDS, PEDIGREE_IDS, EDGE_FLAGS), a field array its components times its
// tuples, a LOOKUP_TABLE of size n 4 n. The walk ends, saying nothing, at an array of strings
// (whose values are words) or a keyword it does not know.
std::string LegacyCellsProblem(const std::string& fileName)
{
  LegacyWords in(fileName);
  if (!in.Ascii())
  {
    return {};
  }
  const bool offsets = in.Version >= 5.0;
  static const std::set<std::string> cellKeywords = { "VERTICES", "LINES", "POLYGONS",
    "TRIANGLE_STRIPS", "CELLS" };
  long long points = -1, cells = -1;
  long long totalCells = -1; // the cells of all cell blocks so far
  long long items = -1;  // the points or cells of the data section (POINT_DATA n, CELL_DATA n)
  std::string section;   // its line ("POINT_DATA 100")
  std::string after; // the block or array just read, for a number after its last value
  bool afterArray = false;
  std::string word, value;
  while (in.Next(word))
  {
    if (!after.empty() && LegacyNumber(word))
    {
      return fileName + ":" + std::to_string(in.Line()) + ": a number (" + QuotedWord(word) +
        ") after the last value of " + after +
        (afterArray ? ": the array holds more values than declared"
                    : ": the block holds more than its line declares");
    }
    long long number = 0;
    const long line = in.Line();
    const std::string keyword = UpperCase(word);
    after.clear();
    afterArray = false;
    if (keyword == "METADATA")
    {
      in.SkipMetadata(); // the information keys of the array before it
      continue;
    }
    if (keyword == "DATASET")
    {
      in.Next(word);
      continue;
    }
    if (keyword == "POINTS")
    {
      if (!in.Next(word) || !WholeNumber(word, points) || !in.Next(value) ||
        points > std::numeric_limits<long long>::max() / 3)
      {
        return {};
      }
      for (long long v = 0; v < 3 * points; ++v)
      {
        if (!in.Next(value))
        {
          return {};
        }
      }
      continue;
    }
    if (cellKeywords.count(keyword) && points >= 0)
    {
      const std::string problem =
        LegacyCellBlockProblem(in, fileName, keyword, offsets, points, cells);
      if (!problem.empty())
      {
        return problem;
      }
      totalCells = std::max(totalCells, 0LL) + cells;
      after = "the " + keyword + " block (line " + std::to_string(line) + ")";
      continue;
    }
    if (keyword == "CELL_TYPES")
    {
      long long n = 0;
      if (!in.Next(word) || !WholeNumber(word, n))
      {
        return {};
      }
      if (cells >= 0 && n != cells)
      {
        return fileName + ":" + std::to_string(line) + ": the CELL_TYPES line declares " +
          std::to_string(n) + " cell types for the " + std::to_string(cells) +
          " cells of the CELLS block";
      }
      for (long long v = 0; v < n; ++v)
      {
        if (!in.Next(word))
        {
          return fileName + ": the CELL_TYPES block (line " + std::to_string(line) +
            ") declares " + std::to_string(n) + " cell types; the file ends after " +
            std::to_string(v) + " of them";
        }
        if (!WholeNumber(word, number))
        {
          return fileName + ":" + std::to_string(in.Line()) + ": " + QuotedWord(word) +
            " where cell type " + std::to_string(v) + " (counting from 0) of the " +
            std::to_string(n) + " that the CELL_TYPES line (line " + std::to_string(line) +
            ") declares should be: the block holds fewer than declared";
        }
      }
      after = "the CELL_TYPES block (line " + std::to_string(line) + ")";
      continue;
    }
    if (keyword == "DIMENSIONS")
    {
      for (int d = 0; d < 3; ++d)
      {
        if (!in.Next(word))
        {
          return {};
        }
      }
      continue;
    }
    if (keyword == "POINT_DATA" || keyword == "CELL_DATA")
    {
      const bool pointData = keyword == "POINT_DATA";
      if (!in.Next(word))
      {
        return {};
      }
      if (!WholeNumber(word, items))
      {
        return fileName + ":" + std::to_string(line) + ": the " + keyword + " line declares " +
          QuotedWord(word) + (pointData ? " points" : " cells") + ", not a whole number of 0 or more";
      }
      // VTK's reader says "Number of cells don't match number data values!" for a CELL_DATA
      // line of other cells than the data set's; for POINT_DATA it reads on, misaligned.
      const long long declared = pointData ? points : totalCells;
      if (declared >= 0 && items != declared)
      {
        return fileName + ":" + std::to_string(line) + ": the " + keyword + " line declares " +
          std::to_string(items) +
          (pointData ? " points, but the POINTS line declares " : " cells, but the cell blocks hold ") +
          std::to_string(declared) + " (a corrupt count)";
      }
      section = keyword + " " + word;
      continue;
    }
    // An attribute array: `KEYWORD name type` (and its components, per keyword).
    std::string name, type;
    long long per = 1;
    std::string perText;
    auto stringType = [](const std::string& t) {
      const std::string upper = UpperCase(t);
      return upper == "STRING" || upper == "UTF8_STRING" || upper == "VARIANT";
    };
    if (keyword == "SCALARS" || keyword == "VECTORS" || keyword == "NORMALS" ||
      keyword == "TENSORS" || keyword == "TENSORS6" || keyword == "TEXTURE_COORDINATES" ||
      keyword == "COLOR_SCALARS" || keyword == "GLOBAL_IDS" || keyword == "PEDIGREE_IDS" ||
      keyword == "EDGE_FLAGS")
    {
      if (items < 0 || !in.Next(name) || !in.Next(type))
      {
        return {};
      }
      if (keyword == "SCALARS")
      {
        // SCALARS name type [components], then LOOKUP_TABLE name.
        if (!in.Next(word))
        {
          return {};
        }
        if (UpperCase(word) != "LOOKUP_TABLE")
        {
          if (!WholeNumber(word, per) || per < 1 || !in.Next(word) ||
            UpperCase(word) != "LOOKUP_TABLE")
          {
            return {};
          }
        }
        if (!in.Next(word))
        {
          return {};
        }
      }
      else if (keyword == "TEXTURE_COORDINATES")
      {
        // TEXTURE_COORDINATES name dimension type.
        if (!WholeNumber(type, per) || per < 1 || !in.Next(type))
        {
          return {};
        }
      }
      else if (keyword == "COLOR_SCALARS")
      {
        // COLOR_SCALARS name components (values from 0 to 1 in ASCII files).
        if (!WholeNumber(type, per) || per < 1)
        {
          return {};
        }
        type = "float";
      }
      else if (keyword == "VECTORS" || keyword == "NORMALS")
      {
        per = 3;
      }
      else if (keyword == "TENSORS")
      {
        per = 9;
      }
      else if (keyword == "TENSORS6")
      {
        per = 6;
      }
      if (stringType(type))
      {
        return {};
      }
      perText = std::to_string(per) + " component" + (per == 1 ? "" : "s");
      const std::string what =
        "the " + keyword + " array " + QuotedWord(name) + " (line " + std::to_string(line) + ")";
      const std::string problem = LegacyValuesProblem(
        in, fileName, what, items, per, section + ", " + perText + " each");
      if (!problem.empty())
      {
        return problem;
      }
      after = what;
      afterArray = true;
      continue;
    }
    if (keyword == "LOOKUP_TABLE")
    {
      long long size = 0;
      if (!in.Next(name) || !in.Next(word) || !WholeNumber(word, size))
      {
        return {};
      }
      const std::string what =
        "the LOOKUP_TABLE " + QuotedWord(name) + " (line " + std::to_string(line) + ")";
      const std::string problem =
        LegacyValuesProblem(in, fileName, what, size, 4, "size " + word + ", 4 values each");
      if (!problem.empty())
      {
        return problem;
      }
      after = what;
      afterArray = true;
      continue;
    }
    if (keyword == "FIELD")
    {
      long long arrays = 0;
      if (!in.Next(name) || !in.Next(word) || !WholeNumber(word, arrays))
      {
        return {};
      }
      for (long long a = 0; a < arrays; ++a)
      {
        std::string components, tuples;
        if (!in.Next(name))
        {
          return {};
        }
        if (name == "METADATA")
        {
          in.SkipMetadata(); // the information keys of the array before it
          --a;
          continue;
        }
        if (a > 0 && LegacyNumber(name))
        {
          return fileName + ":" + std::to_string(in.Line()) + ": a number (" + QuotedWord(name) +
            ") after the last value of " + after + ": the array holds more values than declared";
        }
        if (name == "NULL_ARRAY")
        {
          continue;
        }
        const long arrayLine = in.Line();
        long long c = 0, t = 0;
        if (!in.Next(components) || !in.Next(tuples) || !in.Next(type) || stringType(type))
        {
          return {};
        }
        if (!WholeNumber(components, c) || !WholeNumber(tuples, t))
        {
          // VTK's reader crashes on a negative count.
          return fileName + ":" + std::to_string(arrayLine) + ": the field array " +
            QuotedWord(name) + " declares " + QuotedWord(components) + " components and " +
            QuotedWord(tuples) + " tuples: not whole numbers of 0 or more (a corrupt count)";
        }
        const std::string what = "the field array " + QuotedWord(name) + " (line " +
          std::to_string(arrayLine) + ")";
        const std::string problem = LegacyValuesProblem(
          in, fileName, what, t, c, tuples + " tuples of " + components + " components");
        if (!problem.empty())
        {
          return problem;
        }
        after = what;
        afterArray = true;
      }
      continue;
    }
    return {};
  }
  return {};
}

// Why VTK's legacy reader failed on a binary file, where it says only "Error reading binary
// data!": the first block of binary values (points, cells, point or cell data, field arrays)
// that the file ends inside, with its header's line. Each block's size follows from its header
// and the section's count (the legacy format's types: bit, 1-, 2-, 4- and 8-byte values; ids as
// 4-byte ints before version 5, offsets and connectivity as their declared type from 5 on).
// Empty when the file is not binary, holds string arrays, a keyword this walk does not know, or
// no block cut short (VTK's message then stands).
std::string LegacyBinaryProblem(const std::string& fileName)
{
  std::ifstream file(fileName, std::ios::binary | std::ios::ate);
  if (!file)
  {
    return {};
  }
  const long long size = static_cast<long long>(file.tellg());
  file.seekg(0);
  std::string line;
  long number = 0;
  long long lineStart = 0; // the byte where the line last read starts
  auto next = [&](std::vector<std::string>& words) {
    words.clear();
    while (words.empty())
    {
      lineStart = static_cast<long long>(file.tellg());
      if (!std::getline(file, line))
      {
        break;
      }
      ++number;
      std::istringstream in(line);
      for (std::string w; in >> w;)
      {
        words.push_back(w);
      }
    }
    return !words.empty();
  };
  // A METADATA block: its lines up to an empty one.
  auto skipMetadata = [&]() {
    while (std::getline(file, line) && !line.empty())
    {
      ++number;
    }
    ++number;
  };
  // The line just read, quoted for a message.
  auto quotedLine = [&line]() {
    return "'" + vtkPointCloudIO::MessageText(line.substr(0, 60).c_str()) + "'";
  };
  std::vector<std::string> words;
  double version = 0.0;
  for (int header = 0; header < 3; ++header)
  {
    if (!std::getline(file, line))
    {
      return {};
    }
    ++number;
    if (header == 0)
    {
      const size_t at = line.find("Version");
      version = at == std::string::npos ? 0.0 : std::atof(line.c_str() + at + 7);
    }
    if (header == 2)
    {
      std::string format = line;
      format.erase(std::remove_if(format.begin(), format.end(),
                     [](unsigned char c) { return std::isspace(c) != 0; }),
        format.end());
      if (UpperCase(format) != "BINARY")
      {
        return {};
      }
    }
  }
  // Products of declared counts, saturated (a corrupt count is only ever compared with the
  // file's size).
  auto mul = [](long long a, long long b) -> long long {
    const double product = static_cast<double>(a) * static_cast<double>(b);
    return product > 4e18 ? 4000000000000000000LL : a * b;
  };
  // A type's bytes as VTK's reader matches it: lower-cased, by its first letters, in its order;
  // -2 for strings (their sizes are not declared), -1 for no type of the format.
  auto bytesOf = [mul](const std::string& type, long long values) -> long long {
    static const std::pair<const char*, int> sizes[] = { { "bit", 0 }, { "unsigned_char", 1 },
      { "char", 1 }, { "unsigned_short", 2 }, { "short", 2 }, { "unsigned_int", 4 }, { "int", 4 },
      { "unsigned_long", 8 }, { "long", 8 }, { "float", 4 }, { "double", 8 }, { "vtkidtype", 4 },
      { "vtktypeint64", 8 }, { "vtktypeuint64", 8 }, { "string", -2 }, { "utf8_string", -2 },
      { "variant", -2 } };
    std::string lower = type;
    std::transform(lower.begin(), lower.end(), lower.begin(),
      [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
    for (const auto& size : sizes)
    {
      if (lower.compare(0, std::strlen(size.first), size.first) == 0)
      {
        return size.second == 0 ? (values + 7) / 8
          : size.second < 0     ? -2
                                : mul(size.second, values);
      }
    }
    return -1;
  };
  // Skips a block of `bytes` after the line just read; the problem when the file ends inside it.
  std::string problem;
  bool binaryBefore = false;
  std::string lastBlock; // the line of the block just skipped, and its size
  auto block = [&](long long bytes, const std::string& what) {
    const long long at = static_cast<long long>(file.tellg());
    if (bytes == -1)
    {
      // VTK's reader says "Unsupported data type: ..." without the line.
      problem = fileName + (binaryBefore ? std::string() : ":" + std::to_string(number)) + ": " +
        what + (binaryBefore ? " at byte " + std::to_string(lineStart) : std::string()) +
        " names no type of the legacy format (bit, unsigned_char, char, unsigned_short, short, "
        "unsigned_int, int, unsigned_long, long, float, double, vtkIdType, vtktypeint64, "
        "vtktypeuint64, string)";
      return false;
    }
    if (bytes < 0 || at < 0)
    {
      return false;
    }
    lastBlock = what + " at byte " + std::to_string(lineStart) + " and its " +
      std::to_string(bytes) + " bytes";
    if (at + bytes > size)
    {
      // Past the first binary block, line numbers mean nothing to an editor: the byte.
      problem = fileName + (binaryBefore ? std::string() : ":" + std::to_string(number)) + ": " +
        what + (binaryBefore ? " at byte " + std::to_string(lineStart) : std::string()) +
        " needs " + (bytes >= 4000000000000000000LL ? std::string("more than 4e18") : std::to_string(bytes)) +
        " bytes of binary data after it, but the file ends " +
        std::to_string(size - at) + " bytes after it (a file cut short)";
      return false;
    }
    file.seekg(at + bytes);
    binaryBefore = binaryBefore || bytes > 0;
    return true;
  };
  long long items = 0; // the current section's points or cells
  long long points = -1, cells = -1; // the POINTS line's points; the cell blocks' cells so far
  const bool ids64 = version >= 5.0;
  // A big-endian integer of `bytes` bytes at byte `at` of the file (read through a window of
  // 64 KiB); false past the file's end.
  std::vector<char> window;
  long long windowStart = -1;
  auto integerAt = [&](long long at, int bytes, bool isSigned, long long& value) {
    if (windowStart < 0 || at < windowStart ||
      at + bytes > windowStart + static_cast<long long>(window.size()))
    {
      window.resize(size_t(1) << 16);
      file.clear();
      file.seekg(at);
      file.read(window.data(), static_cast<std::streamsize>(window.size()));
      window.resize(static_cast<size_t>(file.gcount()));
      file.clear();
      windowStart = at;
      if (static_cast<long long>(window.size()) < bytes)
      {
        return false;
      }
    }
    uint64_t bits = 0;
    for (int b = 0; b < bytes; ++b)
    {
      bits = (bits << 8) | static_cast<unsigned char>(window[static_cast<size_t>(at - windowStart + b)]);
    }
    if (isSigned && bytes < 8 && (bits >> (8 * bytes - 1)) != 0)
    {
      bits |= ~uint64_t(0) << (8 * bytes); // sign-extended
    }
    value = !isSigned && bits > uint64_t(std::numeric_limits<long long>::max())
      ? std::numeric_limits<long long>::max()
      : static_cast<long long>(bits);
    return true;
  };
  // Where a line stands in a message: its number before the first binary block, its byte after.
  auto located = [&](const std::string& what) {
    return fileName + (binaryBefore ? std::string() : ":" + std::to_string(number)) + ": " +
      what + (binaryBefore ? " at byte " + std::to_string(lineStart) : std::string());
  };
  while (next(words))
  {
    const std::string keyword = UpperCase(words[0]);
    long long n = 0, m = 0;
    const std::string quoted = quotedLine();
    const std::string previousBlock = lastBlock; // the block before this line, if any
    lastBlock.clear();
    // A problem of this line as a cells line (past binary data, its byte instead of its number).
    auto cellsLine = [&](const std::string& what) {
      return fileName + (binaryBefore ? std::string() : ":" + std::to_string(number)) +
        ": the cells line " + quoted +
        (binaryBefore ? " at byte " + std::to_string(lineStart) : std::string()) + " " + what;
    };
    if (keyword == "DATASET")
    {
      continue;
    }
    if (keyword == "POINTS" && words.size() >= 3 && WholeNumber(words[1], n))
    {
      if (!block(bytesOf(words[2], mul(3, n)), "the POINTS line " + quoted))
      {
        return problem;
      }
      points = n;
    }
    else if ((keyword == "VERTICES" || keyword == "LINES" || keyword == "POLYGONS" ||
               keyword == "TRIANGLE_STRIPS" || keyword == "CELLS") &&
      words.size() >= 3 && !(WholeNumber(words[1], n) && WholeNumber(words[2], m)))
    {
      // VTK's reader reads such a count as a huge one (and crashes) or fails without a word.
      return cellsLine("declares counts that are not whole numbers of 0 or more");
    }
    else if ((keyword == "VERTICES" || keyword == "LINES" || keyword == "POLYGONS" ||
               keyword == "TRIANGLE_STRIPS" || keyword == "CELLS") &&
      words.size() >= 3)
    {
      if (!ids64 && m < n)
      {
        // Each cell holds at least its own number of points.
        return cellsLine("declares " + std::to_string(n) + " cells in " + std::to_string(m) +
          " values: each cell holds at least its number of points");
      }
      if (!ids64)
      {
        if (!block(mul(4, m), "the cells line " + quoted))
        {
          return problem;
        }
        // n cells, each its number of points k and k point ids, in m 4-byte ints: each k must
        // leave its ids within the m values (VTK's reader crashes on a huge one, or says "Number
        // of cells don't match number data values!").
        const long long start = static_cast<long long>(file.tellg()) - 4 * m;
        long long used = 0;
        for (long long c = 0; c < n; ++c)
        {
          long long k = 0;
          const long long byte = start + 4 * used;
          if (used >= m || !integerAt(byte, 4, true, k))
          {
            return cellsLine("declares " + std::to_string(n) + " cells in " + std::to_string(m) +
              " values, but its first " + std::to_string(c) + " cells hold all " +
              std::to_string(m) + " (a corrupt count or size)");
          }
          if (k < 0 || k > m - used - 1)
          {
            return located("cell " + std::to_string(c) + " (counting from 0) of the cells line " +
                     quoted) +
              " declares " + std::to_string(k) + (k == 1 ? " point" : " points") + " at byte " +
              std::to_string(byte) +
              (k < 0 ? std::string(", not a count of 0 or more")
                     : ": more than the " + std::to_string(m - used - 1) +
                    (m - used - 1 == 1 ? " value" : " values") + " left of the " +
                    std::to_string(m) + " that its line declares") +
              " (a corrupt count)";
          }
          used += 1 + k;
        }
        if (used != m)
        {
          return cellsLine("declares " + std::to_string(n) + " cells in " + std::to_string(m) +
            " values, but its cells hold " + std::to_string(used) + " (a corrupt count or size)");
        }
        file.seekg(start + 4 * m);
        cells = std::max(cells, 0LL) + n;
        continue;
      }
      // Version 5: OFFSETS (n values) and CONNECTIVITY (m values), each with its type.
      const std::string cellsQuoted = quoted;
      const long long cellsStart = lineStart;
      for (int part = 0; part < 2; ++part)
      {
        const long long values = part == 0 ? n : m;
        if (!next(words) || words.size() < 2)
        {
          return {};
        }
        const std::string what = "the line " + quotedLine();
        if (!block(bytesOf(words[1], values), what))
        {
          return problem;
        }
        // The offsets: from 0, never decreasing, the last the connectivity's m values (VTK's
        // reader crashes on others).
        const int bytes = static_cast<int>(bytesOf(words[1], 1));
        if (part == 1 || bytes <= 0 || bytes > 8)
        {
          continue;
        }
        const bool isSigned = words[1].compare(0, 8, "unsigned") != 0 && words[1] != "vtktypeuint64";
        const long long start = static_cast<long long>(file.tellg()) - bytes * n;
        long long previous = 0;
        for (long long v = 0; v < n; ++v)
        {
          long long offset = 0;
          const long long byte = start + bytes * v;
          if (!integerAt(byte, bytes, isSigned, offset))
          {
            return {};
          }
          const std::string which =
            located("offset " + std::to_string(v) + " (counting from 0) of " + what) + " is " +
            std::to_string(offset) + " (at byte " + std::to_string(byte) + ")";
          if (v == 0 && offset != 0)
          {
            return which + ", not 0 (a corrupt offset)";
          }
          if (offset < previous)
          {
            return which + ", less than the one before it (" + std::to_string(previous) +
              "; a corrupt offset)";
          }
          if (v == n - 1 && offset != m)
          {
            return which + ", the last, but the cells line " + cellsQuoted + " at byte " +
              std::to_string(cellsStart) + " declares " + std::to_string(m) +
              " connectivity values (a corrupt offset or count)";
          }
          previous = offset;
        }
        file.seekg(start + bytes * n);
      }
      cells = std::max(cells, 0LL) + std::max(n - 1, 0LL);
    }
    else if (keyword == "CELL_TYPES" && words.size() >= 2 && WholeNumber(words[1], n))
    {
      if (cells >= 0 && n != cells)
      {
        return located("the CELL_TYPES line " + quoted) + " declares " + std::to_string(n) +
          " cell types for the " + std::to_string(cells) + " cells of the cells block (a corrupt count)";
      }
      if (!block(mul(4, n), "the CELL_TYPES line " + quoted))
      {
        return problem;
      }
    }
    else if ((keyword == "POINT_DATA" || keyword == "CELL_DATA") && words.size() >= 2 &&
      !WholeNumber(words[1], n))
    {
      return located("the " + keyword + " line " + quoted) + " declares " + QuotedWord(words[1]) +
        (keyword == "POINT_DATA" ? " points" : " cells") + ", not a whole number of 0 or more";
    }
    else if (keyword == "POINT_DATA" || keyword == "CELL_DATA")
    {
      // VTK's reader says "Number of cells don't match number data values!" for a CELL_DATA
      // line of other cells than the data set's; for POINT_DATA it reads on, misaligned.
      const long long declared = keyword == "POINT_DATA" ? points : cells;
      if (declared >= 0 && n != declared)
      {
        return located("the " + keyword + " line " + quoted) + " declares " + std::to_string(n) +
          (keyword == "POINT_DATA" ? " points, but the POINTS line declares "
                                   : " cells, but the cell blocks hold ") +
          std::to_string(declared) + " (a corrupt count)";
      }
      items = n;
    }
    else if (keyword == "SCALARS" && words.size() >= 3)
    {
      long long components = 1;
      if (words.size() >= 4 && !WholeNumber(words[3], components))
      {
        return {};
      }
      const std::string type = words[2];
      const std::string what = "the SCALARS line " + quoted;
      const long scalarsLine = number;
      const long long scalarsStart = lineStart;
      if (!next(words))
      {
        return {};
      }
      number = scalarsLine; // the message names the SCALARS line
      lineStart = scalarsStart;
      if (UpperCase(words[0]) != "LOOKUP_TABLE")
      {
        return {};
      }
      if (!block(bytesOf(type, mul(items, components)), what))
      {
        return problem;
      }
    }
    else if ((keyword == "VECTORS" || keyword == "NORMALS" || keyword == "TENSORS") &&
      words.size() >= 3)
    {
      const long long per = keyword == "TENSORS" ? 9 : 3;
      if (!block(bytesOf(words[2], mul(items, per)), "the " + keyword + " line " + quoted))
      {
        return problem;
      }
    }
    else if (keyword == "TEXTURE_COORDINATES" && words.size() >= 4 && WholeNumber(words[2], n))
    {
      if (!block(bytesOf(words[3], mul(items, n)), "the TEXTURE_COORDINATES line " + quoted))
      {
        return problem;
      }
    }
    else if (keyword == "COLOR_SCALARS" && words.size() >= 3 && WholeNumber(words[2], n))
    {
      if (!block(mul(items, n), "the COLOR_SCALARS line " + quoted))
      {
        return problem;
      }
    }
    else if (keyword == "LOOKUP_TABLE" && words.size() >= 3 && WholeNumber(words[2], n))
    {
      if (!block(mul(4, n), "the LOOKUP_TABLE line " + quoted))
      {
        return problem;
      }
    }
    else if (keyword == "FIELD" && words.size() >= 3 && WholeNumber(words[2], n))
    {
      const std::string field = located("the FIELD line " + quoted);
      const std::string fieldLine = "the FIELD line " + quoted +
        (binaryBefore ? " at byte " + std::to_string(lineStart)
                      : " (line " + std::to_string(number) + ")");
      for (long long a = 0; a < n; ++a)
      {
        if (!next(words))
        {
          // VTK's reader fails without a word.
          return field + " declares " + std::to_string(n) + " arrays; the file ends after " +
            std::to_string(a) + " of them";
        }
        static const std::set<std::string> sections = { "POINT_DATA", "CELL_DATA", "FIELD",
          "POINTS", "VERTICES", "LINES", "POLYGONS", "TRIANGLE_STRIPS", "CELLS", "CELL_TYPES" };
        if (words.size() < 4 && sections.count(UpperCase(words[0])))
        {
          return fileName + ": " + quotedLine() + " at byte " + std::to_string(lineStart) +
            " where array " + std::to_string(a) + " (counting from 0) of the " +
            std::to_string(n) + " that " + fieldLine +
            " declares should be: the field holds fewer arrays than declared";
        }
        if (words[0] == "METADATA")
        {
          --a; // not an array
          skipMetadata();
          continue;
        }
        long long components = 0, tuples = 0;
        if (words.size() < 4)
        {
          return {};
        }
        if (!WholeNumber(words[1], components) || !WholeNumber(words[2], tuples))
        {
          // VTK's reader crashes on a negative count.
          return located("the field array line " + quotedLine()) + " declares " +
            QuotedWord(words[1]) + " components and " + QuotedWord(words[2]) +
            " tuples: not whole numbers of 0 or more (a corrupt count)";
        }
        const std::string what = "the field array line " + quotedLine();
        if (!block(bytesOf(words[3], mul(components, tuples)), what))
        {
          return problem;
        }
      }
    }
    else if (keyword == "METADATA")
    {
      skipMetadata();
    }
    else if (!previousBlock.empty() && !std::all_of(words[0].begin(), words[0].end(), [](char c) {
               return std::isalpha(static_cast<unsigned char>(c)) || c == '_';
             }))
    {
      // Binary data where a keyword should follow a block: the block is not as long as its line
      // declares (VTK's reader says "Unrecognized keyword: " and the bytes).
      std::string shown = words[0].substr(0, 20);
      for (char& c : shown)
      {
        c = (c >= 32 && c < 127) ? c : '?';
      }
      return fileName + ": byte " + std::to_string(lineStart) + ", after " + previousBlock +
        ", holds no keyword ('" + shown + (words[0].size() > 20 ? "..." : "") +
        "'): the block's line declares another count or type than its data have, or the file is "
        "corrupt there";
    }
    else
    {
      return {}; // a keyword this walk does not follow: VTK's message stands
    }
  }
  return {};
}

// Why VTK's legacy reader failed on a file, in its words where it has none worth reading: the
// points (LegacyPointsProblem), the cells (LegacyCellsProblem) of an ASCII file, the binary
// blocks of a binary one (LegacyBinaryProblem); "" when none of them finds anything.
std::string LegacyProblem(const std::string& fileName)
{
  std::string problem = LegacyPointsProblem(fileName);
  if (problem.empty())
  {
    problem = LegacyCellsProblem(fileName);
  }
  return problem.empty() ? LegacyBinaryProblem(fileName) : problem;
}

// The XML of a VTK XML file up to its "<AppendedData" tag (at most its first 64 MB where it has
// none) into `head`; returns where that tag starts (npos: none).
size_t ReadXMLHead(std::ifstream& in, std::string& head)
{
  std::vector<char> chunk(1 << 16);
  size_t appended = std::string::npos;
  while (in && appended == std::string::npos && head.size() < (size_t(64) << 20))
  {
    const size_t from = head.size() > 16 ? head.size() - 16 : 0; // the tag may straddle reads
    in.read(chunk.data(), static_cast<std::streamsize>(chunk.size()));
    head.append(chunk.data(), static_cast<size_t>(in.gcount()));
    appended = head.find("<AppendedData", from);
  }
  return appended;
}

// The DataArray tags of `head` before `end`: where each starts, and its text.
std::vector<std::pair<size_t, std::string>> DataArrayTags(const std::string& head, size_t end)
{
  std::vector<std::pair<size_t, std::string>> tags;
  for (size_t tag = head.find("<DataArray"); tag < end; tag = head.find("<DataArray", tag + 1))
  {
    const size_t tagEnd = head.find('>', tag);
    if (tagEnd == std::string::npos || tagEnd > end)
    {
      break;
    }
    tags.emplace_back(tag, head.substr(tag, tagEnd - tag));
  }
  return tags;
}

// Bytes per value of the VTK XML types (0 for an unknown type).
int BytesPerValue(const std::string& type)
{
  static const std::map<std::string, int> sizes = { { "Float32", 4 }, { "Float64", 8 },
    { "Int8", 1 }, { "UInt8", 1 }, { "Int16", 2 }, { "UInt16", 2 }, { "Int32", 4 },
    { "UInt32", 4 }, { "Int64", 8 }, { "UInt64", 8 } };
  const auto found = sizes.find(type);
  return found == sizes.end() ? 0 : found->second;
}

// A VTK XML file's declared array sizes against the file's size: VTK's reader allocates what a
// DataArray's NumberOfComponents (times the piece's NumberOfPoints, for the points and point
// data) declares before it reads, and a corrupt count made it spin for minutes or take 16 GB on
// a file of 20 KB. An array must fit in the file's bytes times 1032, deflate's largest
// compression ratio (raw, base64 and ascii data hold fewer values than bytes; zlib and LZ4 no more
// than that): NumberOfComponents a whole number from 1, and one tuple, or every point's, within
// that. Files compressed with LZMA, whose ratio has no such bound, are VTK's reader's to judge.
// head, end: the file's XML up to its AppendedData tag, and where that starts (ReadXMLHead()).
bool CheckDeclaredSizes(const std::string& fileName, double fileSize, const std::string& head,
  size_t end, std::string& error)
{
  const size_t fileTag = head.find("<VTKFile");
  if (fileTag == std::string::npos ||
    TagAttribute(head.substr(fileTag, head.find('>', fileTag) - fileTag), "compressor") ==
      "vtkLZMADataCompressor")
  {
    return true;
  }
  const double capacity = 1032.0 * fileSize;
  for (const auto& [tag, array] : DataArrayTags(head, end))
  {
    // VTK's XML reader keeps names in 256-byte buffers ("Unsupported data type" beyond).
    const std::string longName = TagAttribute(array, "Name");
    size_t decoded = longName.size(); // an entity ("&amp;") is one byte once read
    for (size_t amp = longName.find('&'); amp != std::string::npos; amp = longName.find('&', amp + 1))
    {
      const size_t semicolon = longName.find(';', amp);
      decoded -= semicolon != std::string::npos && semicolon - amp <= 10 ? semicolon - amp : 0;
    }
    if (decoded > 255)
    {
      error = fileName + ": an array's name is " + std::to_string(decoded) +
        " bytes long ('" + longName.substr(0, 24) + "...'): VTK's reader reads at most 255";
      return false;
    }
    const std::string text = TagAttribute(array, "NumberOfComponents");
    if (text.empty())
    {
      continue;
    }
    const std::string name = TagAttribute(array, "Name");
    const std::string what = fileName + ": " +
      (name.empty() ? std::string("an unnamed array") : "array '" + name + "'") +
      " declares NumberOfComponents=\"" + text + "\"";
    uint64_t components = 0;
    const auto parsed = std::from_chars(text.data(), text.data() + text.size(), components);
    if (parsed.ec != std::errc() || parsed.ptr != text.data() + text.size() || components == 0)
    {
      error = what + ": not a whole number of 1 or more";
      return false;
    }
    const int perValue = BytesPerValue(TagAttribute(array, "type"));
    const double bytes = static_cast<double>(components) * (perValue > 0 ? perValue : 1);
    // The points of its piece, for the points and the point data.
    double points = 1.0;
    const size_t piece = head.rfind("<Piece", tag);
    const size_t section = std::max(head.rfind("<Points", tag) == std::string::npos
        ? size_t(0) : head.rfind("<Points", tag) + 1,
      head.rfind("<PointData", tag) == std::string::npos ? size_t(0)
                                                          : head.rfind("<PointData", tag) + 1);
    const size_t closed = std::max(head.rfind("</Points>", tag) == std::string::npos
        ? size_t(0) : head.rfind("</Points>", tag) + 1,
      head.rfind("</PointData>", tag) == std::string::npos ? size_t(0)
                                                            : head.rfind("</PointData>", tag) + 1);
    if (piece != std::string::npos && section > piece + 1 && section > closed)
    {
      const std::string pieceTag = head.substr(piece, head.find('>', piece) - piece);
      const std::string declared = TagAttribute(pieceTag, "NumberOfPoints");
      uint64_t n = 0;
      if (std::from_chars(declared.data(), declared.data() + declared.size(), n).ec == std::errc())
      {
        points = std::max(1.0, static_cast<double>(n));
      }
    }
    if (bytes * points > capacity)
    {
      char total[64];
      std::snprintf(total, sizeof(total), "%.4g", bytes * points);
      error = what +
        (points > 1.0 ? " for " + std::to_string(static_cast<uint64_t>(points)) + " points"
                      : std::string()) +
        ": " + total + " bytes, more than a file of " +
        std::to_string(static_cast<uint64_t>(fileSize)) + " bytes can hold (a corrupt count)";
      return false;
    }
  }
  return true;
}

// Each piece's counts (NumberOfPoints, NumberOfCells, NumberOfVerts, ...): VTK's reader takes a
// count it cannot parse, or one beyond 64 bits, for a missing attribute ("Piece 0 is missing its
// NumberOfPoints attribute"), and a negative one for an array too short. A count present must be
// a whole number of 0 or more that fits in 63 bits.
bool CheckPieceCounts(
  const std::string& fileName, const std::string& head, size_t end, std::string& error)
{
  static const char* const counts[] = { "NumberOfPoints", "NumberOfCells", "NumberOfVerts",
    "NumberOfLines", "NumberOfStrips", "NumberOfPolys" };
  int index = 0;
  for (size_t piece = head.find("<Piece"); piece < end; piece = head.find("<Piece", piece + 1))
  {
    const size_t tagEnd = head.find('>', piece);
    if (tagEnd == std::string::npos || tagEnd > end)
    {
      break;
    }
    const std::string tag = head.substr(piece, tagEnd - piece);
    for (const char* name : counts)
    {
      const std::string text = TagAttribute(tag, name);
      uint64_t count = 0;
      if (!text.empty() &&
        (!ParseOffset(text, count) || count > static_cast<uint64_t>(VTK_ID_MAX)))
      {
        error = fileName + ": piece " + std::to_string(index) + " declares " + name + "=\"" +
          vtkPointCloudIO::MessageText(text.substr(0, 40).c_str()) + (text.size() > 40 ? "..." : "") +
          "\": not a whole number from 0 to 2^63 - 1 (a corrupt count)";
        return false;
      }
    }
    ++index;
  }
  return true;
}

// An XML attribute's value as the parser gives it: the five named entities and character
// references replaced.
std::string XMLAttributeText(const std::string& text)
{
  std::string out;
  for (size_t i = 0; i < text.size(); ++i)
  {
    const size_t end = text[i] == '&' ? text.find(';', i) : std::string::npos;
    if (end == std::string::npos || end - i > 10)
    {
      out += text[i];
      continue;
    }
    const std::string entity = text.substr(i + 1, end - i - 1);
    static const std::map<std::string, char> named = { { "amp", '&' }, { "lt", '<' },
      { "gt", '>' }, { "quot", '"' }, { "apos", '\'' } };
    const auto found = named.find(entity);
    unsigned long code = 0;
    char* stop = nullptr;
    if (found != named.end())
    {
      out += found->second;
    }
    else if (entity.size() > 1 && entity[0] == '#' &&
      (code = std::strtoul(entity.c_str() + (entity[1] == 'x' ? 2 : 1), &stop,
         entity[1] == 'x' ? 16 : 10),
        stop && *stop == '\0') &&
      code > 0 && code < 0x110000)
    {
      // UTF-8, as the parser hands names on.
      if (code < 0x80)
      {
        out += static_cast<char>(code);
      }
      else if (code < 0x800)
      {
        out += static_cast<char>(0xC0 | (code >> 6));
        out += static_cast<char>(0x80 | (code & 0x3F));
      }
      else if (code < 0x10000)
      {
        out += static_cast<char>(0xE0 | (code >> 12));
        out += static_cast<char>(0x80 | ((code >> 6) & 0x3F));
        out += static_cast<char>(0x80 | (code & 0x3F));
      }
      else
      {
        out += static_cast<char>(0xF0 | (code >> 18));
        out += static_cast<char>(0x80 | ((code >> 12) & 0x3F));
        out += static_cast<char>(0x80 | ((code >> 6) & 0x3F));
        out += static_cast<char>(0x80 | (code & 0x3F));
      }
    }
    else
    {
      out += text[i];
      continue;
    }
    i = end;
  }
  return out;
}

// A String array of a piece's point or cell data in a VTK XML file (VTK's reader crashes on one
// that holds fewer or more strings than its tuples and components call for): its name as the reader
// reads it, whether it is cell data, and what it holds where that can be told from its text (an
// ASCII array: "2 strings for 3 points").
struct XMLStringArray
{
  std::string Name;
  bool Cells = false;
  std::string Holds;
};

std::vector<XMLStringArray> XMLStringArrays(const std::string& fileName)
{
  std::ifstream in(fileName, std::ios::binary);
  std::string head;
  const size_t appended = ReadXMLHead(in, head);
  std::vector<XMLStringArray> found;
  // Whether `tag` lies inside an element `name` (the last "<name" before it, not closed since).
  auto inside = [&head](size_t tag, const std::string& name) {
    const size_t open = head.rfind("<" + name, tag);
    const size_t close = head.rfind("</" + name + ">", tag);
    return open != std::string::npos && (close == std::string::npos || close < open);
  };
  for (const auto& entry : DataArrayTags(head, appended))
  {
    const std::string& tag = entry.second;
    const bool points = inside(entry.first, "PointData");
    const bool cells = inside(entry.first, "CellData");
    const std::string name = TagAttribute(tag, "Name");
    if (TagAttribute(tag, "type") != "String" || (!points && !cells) || name.empty())
    {
      continue; // an unnamed array of point or cell data is not read
    }
    XMLStringArray array;
    array.Name = XMLAttributeText(name);
    array.Cells = cells && !points;
    const size_t piece = head.rfind("<Piece", entry.first);
    const size_t pieceEnd = piece == std::string::npos ? piece : head.find('>', piece);
    const size_t close = head.find("</DataArray>", entry.first);
    long long components = 1, tuples = -1;
    const std::string componentText = TagAttribute(tag, "NumberOfComponents");
    if (pieceEnd != std::string::npos && close != std::string::npos &&
      TagAttribute(tag, "format") == "ascii" &&
      (componentText.empty() || WholeNumber(componentText, components)) &&
      WholeNumber(TagAttribute(head.substr(piece, pieceEnd - piece),
                    array.Cells ? "NumberOfCells" : "NumberOfPoints"),
        tuples))
    {
      // ASCII strings: their bytes as numbers, each string ended by a 0.
      std::istringstream values(head.substr(entry.first + tag.size() + 1,
        close - std::min(close, entry.first + tag.size() + 1)));
      long long strings = 0, index = 0;
      for (std::string word; values >> word; ++index)
      {
        long long code = 0;
        const char* first = word.data() + (word[0] == '-' ? 1 : 0);
        const auto parsed = std::from_chars(first, word.data() + word.size(), code);
        if (parsed.ec != std::errc() || parsed.ptr != word.data() + word.size() || code > 255 ||
          (word[0] == '-' && code > 128))
        {
          array.Holds = QuotedWord(word) + " as value " + std::to_string(index) +
            " (counting from 0), not a character's code";
          break;
        }
        strings += code == 0 ? 1 : 0;
      }
      if (array.Holds.empty())
      {
        array.Holds = std::to_string(strings) + " string" + (strings == 1 ? "" : "s") + " for " +
          std::to_string(tuples) + (array.Cells ? " cell" : " point") + (tuples == 1 ? "" : "s") +
          (components > 1 ? " of " + std::to_string(components) + " components" : std::string());
      }
    }
    found.push_back(array);
  }
  return found;
}

// The value of a base64 digit (0-63); -1 for any other character ('=' included).
int Base64Digit(char c)
{
  static const std::string alphabet =
    "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
  const size_t d = alphabet.find(c);
  return c != '\0' && d != std::string::npos ? static_cast<int>(d) : -1;
}

// Whether a block of `count` bytes (`ascii`: values) for the DataArray tag at `tag` of `head`
// (its text: `array`) holds as many points as its piece's NumberOfPoints, where it is the piece's
// Points array (VTK reads that many and drops or leaves unread the rest, or fills the missing
// ones with zeros); false, with `error`, where it does not.
bool PointsFitBlock(const std::string& fileName, const std::string& head, size_t tag,
  const std::string& array, uint64_t count, std::string& error, bool ascii = false)
{
  const size_t piece = head.rfind("<Piece", tag);
  const size_t points = head.rfind("<Points", tag);
  if (piece == std::string::npos || points == std::string::npos || points < piece ||
    head.find("</Points>", points) < tag)
  {
    return true;
  }
  const std::string pieceTag = head.substr(piece, head.find('>', piece) - piece);
  const std::string declared = TagAttribute(pieceTag, "NumberOfPoints");
  const int bytesPerValue = BytesPerValue(TagAttribute(array, "type"));
  uint64_t n = 0, components = 3;
  const auto parsedPoints = std::from_chars(declared.data(), declared.data() + declared.size(), n);
  const std::string componentsText = TagAttribute(array, "NumberOfComponents");
  if (!componentsText.empty())
  {
    const char* c = componentsText.data();
    std::from_chars(c, c + componentsText.size(), components);
  }
  if (bytesPerValue == 0 || parsedPoints.ec != std::errc() || components == 0 || components > 64)
  {
    return true; // VTK's reader says what is wrong with those
  }
  const uint64_t per = components * static_cast<uint64_t>(ascii ? 1 : bytesPerValue);
  if (n > count / per || n * per != count)
  {
    error = fileName + ": a piece declares NumberOfPoints=\"" + declared + "\", but its " +
      (ascii ? "ASCII " : "") + "Points array holds " + std::to_string(count) +
      (ascii ? (count == 1 ? " value, " : " values, ") : " bytes, ") +
      (count % per == 0 ? std::to_string(count / per) + (count == per ? " point" : " points")
                        : std::string("not a whole number of points"));
    return false;
  }
  return true;
}

// A VTK XML file's raw appended data against the file's size: VTK's reader fills the arrays of a
// file cut short (or an offset before the data) with zeros or with the bytes around, and says
// nothing. Each uncompressed array's block (its byte count, then its bytes) must lie within the
// file. Other encodings and compressed blocks, which VTK's reader checks, pass.
bool CheckAppendedData(const std::string& fileName, double fileSize, std::string& error)
{
  std::ifstream in(fileName, std::ios::binary);
  std::string head;
  const size_t appended = ReadXMLHead(in, head);
  if (appended == std::string::npos)
  {
    return true;
  }
  std::vector<char> chunk(1 << 16);
  size_t close = head.find('>', appended);
  while (close == std::string::npos && in)
  {
    in.read(chunk.data(), static_cast<std::streamsize>(chunk.size()));
    head.append(chunk.data(), static_cast<size_t>(in.gcount()));
    close = head.find('>', appended);
  }
  const size_t fileTag = head.find("<VTKFile");
  const size_t fileTagEnd = fileTag == std::string::npos ? fileTag : head.find('>', fileTag);
  if (close == std::string::npos || fileTagEnd == std::string::npos)
  {
    return true; // VTK's parser reports the broken XML
  }
  const std::string file = head.substr(fileTag, fileTagEnd - fileTag);
  const std::string appendedTag = head.substr(appended, close - appended);
  const std::string compressor = TagAttribute(file, "compressor");
  const std::string encoding = TagAttribute(appendedTag, "encoding");
  const bool base64 = encoding == "base64";
  if (encoding != "raw" && !base64)
  {
    return true;
  }
  const size_t underscore = head.find('_', close);
  if (underscore == std::string::npos)
  {
    return true;
  }
  const uint64_t size = static_cast<uint64_t>(fileSize);
  const uint64_t start = underscore + 1;
  const int headerBytes = TagAttribute(file, "header_type") == "UInt64" ? 8 : 4;
  const bool bigEndian = TagAttribute(file, "byte_order") == "BigEndian";
  // The bytes [from, from + count) of the block at appended offset `offset`, raw or base64 (the
  // block's header encoded on its own, from the offset); false past the end of the file.
  auto bytesAt = [&](uint64_t offset, uint64_t from, int count, unsigned char* out) {
    if (offset > size || from > size)
    {
      return false;
    }
    if (!base64)
    {
      const uint64_t at = start + offset + from;
      if (at + count > size)
      {
        return false;
      }
      in.clear();
      in.seekg(static_cast<std::streamoff>(at));
      in.read(reinterpret_cast<char*>(out), count);
      return in.gcount() == count;
    }
    // Base64: 3 bytes a group of 4 characters.
    const uint64_t first = from / 3, last = (from + count - 1) / 3;
    const uint64_t at = start + offset + 4 * first;
    const size_t chars = static_cast<size_t>(4 * (last - first + 1));
    if (at + chars > size)
    {
      return false;
    }
    std::string text(chars, '\0');
    in.clear();
    in.seekg(static_cast<std::streamoff>(at));
    in.read(&text[0], static_cast<std::streamsize>(chars));
    if (static_cast<size_t>(in.gcount()) != chars)
    {
      return false;
    }
    std::vector<unsigned char> decoded;
    for (size_t g = 0; g < chars; g += 4)
    {
      uint32_t v = 0;
      for (size_t c = 0; c < 4; ++c)
      {
        const int d = text[g + c] == '=' ? 0 : Base64Digit(text[g + c]);
        if (d < 0)
        {
          return false;
        }
        v = (v << 6) | static_cast<uint32_t>(d);
      }
      decoded.push_back(static_cast<unsigned char>(v >> 16));
      decoded.push_back(static_cast<unsigned char>(v >> 8));
      decoded.push_back(static_cast<unsigned char>(v));
    }
    std::copy_n(decoded.begin() + static_cast<std::ptrdiff_t>(from - 3 * first), count, out);
    return true;
  };
  // Reads the header word `k` of the block at appended offset `offset`; false past the end.
  auto word = [&](uint64_t offset, uint64_t k, uint64_t& value) {
    unsigned char bytes[8] = { 0 };
    if (k > size || !bytesAt(offset, k * headerBytes, headerBytes, bytes))
    {
      return false;
    }
    value = 0;
    for (int b = 0; b < headerBytes; ++b)
    {
      value = (value << 8) | bytes[bigEndian ? b : headerBytes - 1 - b];
    }
    return true;
  };
  if (!compressor.empty())
  {
    // Compressed blocks: the number of blocks, the block size, the last block's size, then each
    // block's compressed size. VTK's reader allocates the uncompressed size before it reads: a
    // corrupt header made it take 7.6 GB and 30 s on a file of 19 KB. The headers and the
    // compressed bytes must lie within the file, the uncompressed bytes within 1032 times it
    // (deflate's largest ratio; not for LZMA, which has no such bound).
    for (const auto& tagged : DataArrayTags(head, appended))
    {
      const std::string& array = tagged.second;
      const std::string text = TagAttribute(array, "offset");
      uint64_t offset = 0, blocks = 0, blockSize = 0, lastSize = 0;
      if (TagAttribute(array, "format") != "appended" || !ParseOffset(text, offset))
      {
        continue;
      }
      const std::string name = TagAttribute(array, "Name");
      const std::string what = fileName + ": " +
        (name.empty() ? std::string("an unnamed array") : "array '" + name + "'") +
        " at appended offset " + text;
      if (!word(offset, 0, blocks) || !word(offset, 1, blockSize) || !word(offset, 2, lastSize))
      {
        error = what + ": its compressed block header runs past the end of the file (" +
          std::to_string(size) + " bytes): the file is cut short";
        return false;
      }
      // Blocks of no bytes, or a last block larger than the others: VTK's reader divides by the
      // block size (a floating-point exception). 8-byte sizes read as 4-byte ones give a block
      // size of 0 (the high word of the count).
      if (blocks > 0 && (blockSize == 0 || lastSize > blockSize))
      {
        error = what + " declares " + std::to_string(blocks) + " compressed block(s) of " +
          std::to_string(blockSize) + " bytes, the last of " + std::to_string(lastSize) +
          ": a corrupt header" +
          (headerBytes == 4 && blockSize == 0
              ? std::string(" (or 8-byte sizes read as header_type UInt32, the default)")
              : std::string());
        return false;
      }
      uint64_t compressed = 0, part = 0;
      bool inside = blocks <= size / headerBytes;
      for (uint64_t b = 0; inside && b < blocks; ++b)
      {
        inside = word(offset, 3 + b, part) && part <= size && (compressed += part) <= size;
      }
      const double uncompressed = static_cast<double>(blocks) * static_cast<double>(blockSize);
      // The bytes the header and the compressed blocks take in the file (base64: 4 for 3).
      auto stored = [&](uint64_t n) { return base64 ? 4 * ((n + 2) / 3) : n; };
      if (!inside || start + offset + stored((3 + blocks) * headerBytes) + stored(compressed) > size ||
        (compressor != "vtkLZMADataCompressor" && uncompressed > 1032.0 * fileSize))
      {
        char total[64];
        std::snprintf(total, sizeof(total), "%.4g", uncompressed);
        error = what + " declares " + std::to_string(blocks) + " compressed blocks of " +
          std::to_string(blockSize) + " bytes (" + total + " bytes" +
          (inside ? ", " + std::to_string(compressed) + " compressed" : std::string()) +
          "), more than the file of " + std::to_string(size) +
          " bytes holds: a corrupt header or a file cut short";
        return false;
      }
    }
    return true;
  }
  // The appended arrays (their tags, where they start in head) and their offsets, in order: no
  // block may run into the next one. Arrays not appended, or without an offset, are VTK's
  // reader's to judge.
  std::vector<size_t> tags;
  std::vector<uint64_t> starts;
  for (const auto& [tag, array] : DataArrayTags(head, appended))
  {
    const std::string text = TagAttribute(array, "offset");
    uint64_t offset = 0;
    if (TagAttribute(array, "format") != "appended" || text.empty())
    {
      continue;
    }
    tags.push_back(tag);
    if (ParseOffset(text, offset))
    {
      starts.push_back(offset);
    }
  }
  std::sort(starts.begin(), starts.end());
  // The end of the appended data: where its closing tag starts (searched from the file's end: the
  // raw bytes may hold anything). The last block must end before it.
  uint64_t dataEnd = size;
  {
    const uint64_t tail = std::min<uint64_t>(size, 1 << 16);
    std::string last(static_cast<size_t>(tail), '\0');
    in.clear();
    in.seekg(static_cast<std::streamoff>(size - tail));
    in.read(&last[0], static_cast<std::streamsize>(tail));
    last.resize(static_cast<size_t>(in.gcount()));
    const size_t closing = last.rfind("</AppendedData>");
    if (closing != std::string::npos && size - tail + closing >= start)
    {
      dataEnd = size - tail + closing;
    }
  }
  // Blocks followed by another, and those that leave exactly 4 bytes before it: 8-byte sizes
  // read as 4-byte ones (header_type UInt32, or none, over a file written with UInt64).
  int followed = 0, gapsOfFour = 0;
  for (const size_t tag : tags)
  {
    const std::string array = head.substr(tag, head.find('>', tag) - tag);
    const std::string text = TagAttribute(array, "offset");
    const std::string name = TagAttribute(array, "Name");
    const std::string what = name.empty() ? "an unnamed array" : "array '" + name + "'";
    uint64_t offset = 0;
    if (!ParseOffset(text, offset))
    {
      error = fileName + ": " + what + ": offset '" + text +
        "' into the appended data is not a byte count from its start";
      return false;
    }
    if (offset > size || start + offset + headerBytes > size)
    {
      error = fileName + ": " + what + " starts at appended offset " + text +
        ", past the end of the file (" + std::to_string(size) + " bytes): the file is cut short";
      return false;
    }
    if (base64)
    {
      // The size field, then as many bytes as it declares: 4 characters for 3 bytes, at least
      // (the field encoded on its own, as VTK writes it, or with the data), before the next
      // block or the end of the appended data.
      const auto after = std::upper_bound(starts.begin(), starts.end(), offset);
      const bool lastBlock = after == starts.end();
      const uint64_t blockEnd = lastBlock ? (dataEnd >= start ? dataEnd - start : 0) : *after;
      const uint64_t room = blockEnd >= offset ? blockEnd - offset : 0;
      uint64_t count = 0;
      if (!word(offset, 0, count) || count > size ||
        (4 * (static_cast<uint64_t>(headerBytes) + count) + 2) / 3 > room)
      {
        error = fileName + ": " + what + " at appended offset " + std::to_string(offset) +
          " declares " + std::to_string(count) + " bytes, more than the " +
          std::to_string(room) + " base64 characters before " +
          (lastBlock ? std::string("the end of the appended data")
                     : std::string("the next block")) +
          " can hold: the file is cut short, or the size field is corrupt";
        return false;
      }
      if (!PointsFitBlock(fileName, head, tag, array, count, error))
      {
        return false;
      }
      continue;
    }
    const uint64_t at = start + offset;
    unsigned char bytes[8] = { 0 };
    in.clear();
    in.seekg(static_cast<std::streamoff>(at));
    in.read(reinterpret_cast<char*>(bytes), headerBytes);
    uint64_t count = 0;
    for (int b = 0; b < headerBytes; ++b)
    {
      const int i = bigEndian ? b : headerBytes - 1 - b;
      count = (count << 8) | bytes[i];
    }
    // The next block: a size field read with the wrong width (header_type UInt64 over 4-byte
    // sizes takes the next 4 bytes, the data's first, into the size) or a corrupt size runs
    // into it, and VTK's reader reads the data shifted.
    const auto next = std::upper_bound(starts.begin(), starts.end(), offset);
    const bool last = next == starts.end();
    if (!last)
    {
      ++followed;
      gapsOfFour += *next >= offset && *next - offset >= 8 && count == *next - offset - 8;
    }
    const uint64_t limit = last ? (dataEnd >= start ? dataEnd - start : 0) : *next;
    if ((!last || dataEnd < size) && limit >= offset &&
      (limit - offset < static_cast<uint64_t>(headerBytes) || count > limit - offset - headerBytes))
    {
      const uint64_t room =
        limit - offset > static_cast<uint64_t>(headerBytes) ? limit - offset - headerBytes : 0;
      error = fileName + ": " + what + " at appended offset " + std::to_string(offset) + " holds " +
        std::to_string(count) + " bytes after its " + std::to_string(headerBytes) +
        "-byte size, more than the " + std::to_string(room) + " bytes before " +
        (last ? std::string("the end of the appended data") :
                "the next block, at offset " + std::to_string(*next)) +
        ": its size field (header_type " + (headerBytes == 8 ? "UInt64" : "UInt32") +
        ") does not match the data";
      return false;
    }
    if (count > size || at + headerBytes + count > size)
    {
      error = fileName + ": " + what + " at appended offset " + std::to_string(offset) +
        " holds " + std::to_string(count) + " bytes from byte " +
        std::to_string(at + headerBytes) + ", but the file ends at byte " +
        std::to_string(size) + ": the file is cut short";
      return false;
    }
    if (!PointsFitBlock(fileName, head, tag, array, count, error))
    {
      return false;
    }
  }
  if (headerBytes == 4 && !bigEndian && followed > 0 && gapsOfFour == followed)
  {
    error = fileName + ": every raw appended block leaves 4 bytes unread before the next: its " +
      "size fields are 8 bytes wide, but header_type says UInt32" +
      (TagAttribute(file, "header_type").empty() ? " (its default)" : "") +
      ": a corrupt header_type";
    return false;
  }
  return true;
}

// A VTK XML file's inline binary arrays against their size fields: VTK's reader fills the values
// that a block cut short lacks with zeros, and says nothing. Each uncompressed array's base64 text
// must hold its size field and the bytes that declares (4 characters for 3 bytes, the field
// encoded on its own or with the data), and a piece's Points array its NumberOfPoints points.
// Compressed blocks, whose sizes VTK's reader checks, pass.
// head, appended: as for CheckDeclaredSizes().
bool CheckInlineData(
  const std::string& fileName, const std::string& head, size_t appended, std::string& error)
{
  const size_t end = appended == std::string::npos ? head.size() : appended;
  const size_t fileTag = head.find("<VTKFile");
  const size_t fileTagEnd = fileTag == std::string::npos ? fileTag : head.find('>', fileTag);
  if (fileTagEnd == std::string::npos)
  {
    return true; // VTK's parser reports the broken XML
  }
  const std::string file = head.substr(fileTag, fileTagEnd - fileTag);
  if (!TagAttribute(file, "compressor").empty())
  {
    return true;
  }
  const int headerBytes = TagAttribute(file, "header_type") == "UInt64" ? 8 : 4;
  const bool bigEndian = TagAttribute(file, "byte_order") == "BigEndian";
  for (const auto& [tag, array] : DataArrayTags(head, end))
  {
    if (TagAttribute(array, "format") == "ascii" && !array.empty() && array.back() != '/')
    {
      // An ASCII Points array: its values, the words up to the next tag (VTK reads the first
      // NumberOfPoints points and says nothing of the rest).
      const size_t open = head.find('>', tag) + 1;
      const size_t close = head.find('<', open);
      if (close == std::string::npos || close > end)
      {
        continue;
      }
      uint64_t values = 0;
      for (size_t c = open; c < close;)
      {
        while (c < close && std::isspace(static_cast<unsigned char>(head[c])))
        {
          ++c;
        }
        values += c < close;
        while (c < close && !std::isspace(static_cast<unsigned char>(head[c])))
        {
          ++c;
        }
      }
      if (!PointsFitBlock(fileName, head, tag, array, values, error, true))
      {
        return false;
      }
      continue;
    }
    if (TagAttribute(array, "format") != "binary" || (!array.empty() && array.back() == '/'))
    {
      continue;
    }
    const size_t open = head.find('>', tag) + 1;
    // The data end where the next tag starts: an array's InformationKey elements follow it.
    const size_t close = head.find('<', open);
    if (close == std::string::npos || close > end)
    {
      continue; // past what was read: VTK's reader's to judge
    }
    // The characters of the text other than white space and padding (6 bits each), and from the
    // first of them, the size field.
    uint64_t characters = 0, count = 0;
    std::vector<unsigned char> field;
    uint32_t bits = 0;
    int pending = 0;
    for (size_t c = open; c < close; ++c)
    {
      const char ch = head[c];
      const int d = Base64Digit(ch);
      if (d < 0)
      {
        continue; // white space and padding; anything else is VTK's reader's to judge
      }
      ++characters;
      if (field.size() < static_cast<size_t>(headerBytes))
      {
        bits = (bits << 6) | static_cast<uint32_t>(d);
        pending += 6;
        if (pending >= 8)
        {
          pending -= 8;
          field.push_back(static_cast<unsigned char>(bits >> pending));
          bits &= (1u << pending) - 1u;
        }
      }
    }
    const std::string name = TagAttribute(array, "Name");
    const std::string what = fileName + ": " +
      (name.empty() ? std::string("an unnamed array") : "array '" + name + "'");
    if (field.size() < static_cast<size_t>(headerBytes))
    {
      error = what + " is binary (base64) and holds " + std::to_string(characters) +
        " characters: not even its " + std::to_string(headerBytes) + "-byte size field";
      return false;
    }
    for (int b = 0; b < headerBytes; ++b)
    {
      count = (count << 8) | field[static_cast<size_t>(bigEndian ? b : headerBytes - 1 - b)];
    }
    const uint64_t held = characters / 4 * 3 + (characters % 4) * 3 / 4;
    if (count > held || held - count < static_cast<uint64_t>(headerBytes))
    {
      error = what + " declares " + std::to_string(count) + " bytes of binary (base64) data, " +
        "but its text holds " + std::to_string(held >= static_cast<uint64_t>(headerBytes)
            ? held - static_cast<uint64_t>(headerBytes) : 0) +
        " after its size field: the file is cut short, or the size field is corrupt";
      return false;
    }
    if (!PointsFitBlock(fileName, head, tag, array, count, error))
    {
      return false;
    }
  }
  return true;
}
} // namespace

vtkSmartPointer<vtkCellArray> vtkPointCloudIO::MakeVertexCells(vtkIdType n)
{
  return featurepoints::MakeVertexCells(n);
}

bool vtkPointCloudIO::MakeVertexCells(vtkIdType n, vtkCellArray* cells)
{
  if (!cells)
  {
    return false;
  }
  vtkSmartPointer<vtkCellArray> verts = n >= 0 ? MakeVertexCells(n) : nullptr;
  if (!verts)
  {
    cells->Initialize();
    return false;
  }
  cells->ShallowCopy(verts);
  return true;
}

std::string vtkPointCloudIO::GetExtension(const std::string& fileName)
{
  const size_t slash = fileName.find_last_of('/');
  const size_t dot = fileName.find_last_of('.');
  if (dot == std::string::npos || (slash != std::string::npos && dot < slash) ||
    dot + 1 == fileName.size())
  {
    return "";
  }
  std::string extension = fileName.substr(dot + 1);
  std::transform(extension.begin(), extension.end(), extension.begin(),
    [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return extension;
}

bool vtkPointCloudIO::CanRead(const std::string& extension)
{
  return std::find(std::begin(ReadableExtensions), std::end(ReadableExtensions), extension) !=
    std::end(ReadableExtensions) ||
    std::find(std::begin(RecognizedExtensions), std::end(RecognizedExtensions), extension) !=
    std::end(RecognizedExtensions);
}

bool vtkPointCloudIO::CanWrite(const std::string& extension)
{
  return std::find(std::begin(WritableExtensions), std::end(WritableExtensions), extension) !=
    std::end(WritableExtensions);
}

std::string vtkPointCloudIO::GetReadableExtensions()
{
  return Join(std::begin(ReadableExtensions), std::end(ReadableExtensions));
}

std::string vtkPointCloudIO::GetWritableExtensions()
{
  return Join(std::begin(WritableExtensions), std::end(WritableExtensions));
}

std::string vtkPointCloudIO::OneLine(const std::string& message)
{
  std::string line, word;
  auto flush = [&]() {
    line += word.size() > 1024
      ? word.substr(0, 64) + "... (" + std::to_string(word.size()) + " bytes)"
      : word;
    word.clear();
  };
  for (const char c : message)
  {
    const unsigned char u = static_cast<unsigned char>(c);
    if (c == ' ')
    {
      flush();
      line += c;
    }
    else if (u < 0x20 || u == 0x7f)
    {
      char escaped[8];
      std::snprintf(escaped, sizeof(escaped), "\\x%02x", u);
      word += escaped;
    }
    else
    {
      word += c;
    }
  }
  flush();
  return line;
}

std::string vtkPointCloudIO::MessageText(const char* vtkMessage)
{
  std::string text = vtkMessage ? vtkMessage : "";
  // vtkErrorMacro's text: "ERROR: In FILE, line N\nCLASS (ADDRESS): MESSAGE\n\n".
  // vtkGenericWarningMacro's: "Generic Warning: In FILE, line N\nMESSAGE\n\n".
  const size_t newline = text.find('\n');
  if (text.compare(0, 3, "ERR") == 0 || text.compare(0, 4, "Warn") == 0)
  {
    const size_t start = text.find("): ", newline == std::string::npos ? 0 : newline);
    if (start != std::string::npos)
    {
      text.erase(0, start + 3);
    }
  }
  else if (text.compare(0, 19, "Generic Warning: In") == 0 && newline != std::string::npos)
  {
    text.erase(0, newline + 1);
  }
  for (char& c : text)
  {
    c = (c == '\n' || c == '\r' || c == '\t') ? ' ' : c;
  }
  while (!text.empty() && text.back() == ' ')
  {
    text.pop_back();
  }
  return text;
}

vtkSmartPointer<vtkPointSet> vtkPointCloudIO::Read(
  const std::string& fileName, std::string& error, vtkCommand* observer)
{
  error.clear();
  const std::string extension = GetExtension(fileName);
  // One stat() rather than vtksys: its errno names why a path cannot be read, and it tells FIFOs,
  // devices and sockets apart (vtksys::SystemTools does not), all from the same instant.
  struct stat info;
  if (::stat(fileName.c_str(), &info) != 0)
  {
    error = fileName + ": " + std::strerror(errno);
    return nullptr;
  }
  if (S_ISDIR(info.st_mode))
  {
    error = fileName + ": is a folder, not a file";
    return nullptr;
  }
  if (!S_ISREG(info.st_mode))
  {
    // Opening a FIFO without a writer would block, and a device never ends.
    error = fileName + ": is " +
      (S_ISFIFO(info.st_mode)       ? "a FIFO (named pipe)"
          : S_ISCHR(info.st_mode)   ? "a character device"
          : S_ISBLK(info.st_mode)   ? "a block device"
          : S_ISSOCK(info.st_mode)  ? "a socket"
                                    : "not a plain file") +
      ", not a regular file: point clouds are read from regular files";
    return nullptr;
  }
  if (!CanRead(extension))
  {
    error = fileName + ": cannot tell the format from the extension " +
      (extension.empty() ? std::string("(none)") : "'." + extension + "'") +
      "; readable: " + GetReadableExtensions();
    return nullptr;
  }
  if (FILE* probe = vtksys::SystemTools::Fopen(fileName, "rb"))
  {
    std::fclose(probe);
  }
  else
  {
    error = fileName + ": cannot open: " + std::strerror(errno);
    return nullptr;
  }
  if (info.st_size == 0)
  {
    error = fileName + ": the file is empty";
    return nullptr;
  }

  const bool vtkFormat = extension == "vtp" || extension == "vtu" || extension == "vtk";
  if (extension == "vtp" || extension == "vtu")
  {
    std::ifstream in(fileName, std::ios::binary);
    std::string head;
    const size_t appended = ReadXMLHead(in, head);
    if (!CheckPieceCounts(fileName, head, appended, error) ||
      !CheckDeclaredSizes(fileName, static_cast<double>(info.st_size), head, appended, error) ||
      !CheckAppendedData(fileName, static_cast<double>(info.st_size), error) ||
      !CheckInlineData(fileName, head, appended, error))
    {
      return nullptr;
    }
  }
  if (extension == "vtk" && !CheckLegacyPoints(fileName, static_cast<double>(info.st_size), error))
  {
    return nullptr;
  }
  return vtkFormat ? ReadIsolated(fileName, extension, static_cast<double>(info.st_size), error, observer)
                   : ReadWithReader(fileName, extension, error, observer);
}

bool vtkPointCloudIO::ReadPolyData(
  const std::string& fileName, vtkPolyData* output, std::string& error, vtkCommand* observer)
{
  if (!output)
  {
    error = fileName + ": no polydata to read into";
    return false;
  }
  vtkSmartPointer<vtkPointSet> cloud = Read(fileName, error, observer);
  if (!cloud)
  {
    output->Initialize();
    return false;
  }
  output->ShallowCopy(AsPolyData(cloud));
  if (output->GetNumberOfCells() == 0 && output->GetNumberOfPoints() > 0)
  {
    // Points alone (a .vtp or .vtk cloud written without cells): vertices, so that it renders.
    output->SetVerts(MakeVertexCells(output->GetNumberOfPoints()));
  }
  return true;
}

vtkSmartPointer<vtkPointSet> vtkPointCloudIO::ReadWithReader(const std::string& fileName,
  const std::string& extension, std::string& error, vtkCommand* observer,
  const std::vector<std::pair<std::string, bool>>& leaveOut)
{
  // The arrays to leave out, once the reader knows the file's arrays.
  auto select = [&leaveOut](vtkXMLReader* r) {
    if (leaveOut.empty())
    {
      return;
    }
    ScopedCapture capture(false); // the read below says what is wrong, if anything
    r->UpdateInformation();
    for (const auto& array : leaveOut)
    {
      (array.second ? r->GetCellDataArraySelection() : r->GetPointDataArraySelection())
        ->DisableArray(array.first.c_str());
    }
  };
  vtkSmartPointer<vtkAlgorithm> reader;
  if (extension == "ply")
  {
    auto r = vtkSmartPointer<vtkPointCloudPLYReader>::New();
    r->SetFileName(fileName.c_str());
    reader = r;
  }
  else if (extension == "pcd")
  {
    auto r = vtkSmartPointer<vtkPointCloudPCDReader>::New();
    r->SetFileName(fileName.c_str());
    reader = r;
  }
  else if (extension == "las" || extension == "laz")
  {
    // A .laz file gets the reader's one-line reason why it cannot be read.
    auto r = vtkSmartPointer<vtkPointCloudLASReader>::New();
    r->SetFileName(fileName.c_str());
    reader = r;
  }
  else if (extension == "vtp")
  {
    auto r = vtkSmartPointer<vtkXMLPolyDataReader>::New();
    r->SetFileName(fileName.c_str());
    select(r);
    reader = r;
  }
  else if (extension == "vtu")
  {
    auto r = vtkSmartPointer<vtkXMLUnstructuredGridReader>::New();
    r->SetFileName(fileName.c_str());
    select(r);
    reader = r;
  }
  else if (extension == "vtk")
  {
    auto r = vtkSmartPointer<vtkDataSetReader>::New();
    r->SetFileName(fileName.c_str());
    ScopedCapture capture(true);
    if (r->ReadOutputType() < 0)
    {
      error = fileName + ": not a legacy VTK data set file (no header and DATASET line it can read)";
      return nullptr;
    }
    reader = r;
  }
  else
  {
    auto r = vtkSmartPointer<vtkPointCloudTextReader>::New();
    r->SetFileName(fileName.c_str());
    reader = r;
  }
  // Every message of the read, the reader's own or its parts', ends as the one line of `error`;
  // for the legacy reader a warning is a failure too (a short body is only a warning there).
  ScopedCapture capture(extension == "vtk");
  vtkNew<ErrorCatcher> catcher;
  catcher->First = &capture.Window->Message;
  catcher->Pipeline = &capture.Window->PipelineMessage;
  reader->AddObserver(vtkCommand::ErrorEvent, catcher);
  if (observer)
  {
    reader->AddObserver(vtkCommand::ProgressEvent, observer);
  }
  int updated = 0;
  try
  {
    updated = reader->GetExecutive()->Update();
  }
  catch (const std::exception& e)
  {
    const std::string& first = capture.Window->Text();
    error = WithFile(fileName,
      "cannot read: " + ExceptionText(e) + (first.empty() ? std::string() : " (" + first + ")"));
    return nullptr;
  }
  const std::string& message = capture.Window->Message.empty() &&
      reader->GetErrorCode() != vtkErrorCode::NoError
    ? capture.Window->Message
    : capture.Window->Text();
  if (!updated || !message.empty() || reader->GetErrorCode() != vtkErrorCode::NoError)
  {
    const unsigned long code = reader->GetErrorCode();
    auto legacyProblem = [&fileName]() { return LegacyProblem(fileName); };
    const std::string legacy = extension == "vtk" ? legacyProblem()
      : extension == "vtp" || extension == "vtu"
      ? XMLCompressionProblem(fileName,
          !message.empty() ? message : std::string(vtkErrorCode::GetStringFromErrorCode(code)))
      : std::string();
    if (legacy.empty() && (extension == "vtp" || extension == "vtu") &&
      message.find("Cannot read points array") != std::string::npos)
    {
      error = XMLPointsProblem(fileName);
      if (!error.empty())
      {
        return nullptr;
      }
    }
    if (!legacy.empty())
    {
      error = legacy;
      return nullptr;
    }
    const bool ours = extension != "vtp" && extension != "vtu" && extension != "vtk";
    error = WithFile(fileName,
      !message.empty() ? (ours ? message : "cannot read: " + message)
        : code != vtkErrorCode::NoError
        ? std::string("cannot read: ") + vtkErrorCode::GetStringFromErrorCode(code)
        : std::string("cannot read: not a valid ." + extension + " file"));
    return nullptr;
  }
  vtkDataObject* output = reader->GetOutputDataObject(0);
  vtkPointSet* points = vtkPointSet::SafeDownCast(output);
  if (!points)
  {
    error = fileName + ": holds " + (output ? output->GetClassName() : std::string("no data")) +
      ", not a point set";
    return nullptr;
  }
  if (points->GetNumberOfPoints() == 0 && (extension == "vtp" || extension == "vtu"))
  {
    error = XMLPointsProblem(fileName);
    if (!error.empty())
    {
      return nullptr; // else no point, and the caller says so
    }
  }
  // A malformed legacy file can leave arrays shorter than the points.
  vtkPointData* pd = points->GetPointData();
  for (int a = 0; a < pd->GetNumberOfArrays(); ++a)
  {
    vtkAbstractArray* array = pd->GetAbstractArray(a);
    if (array && array->GetNumberOfTuples() != points->GetNumberOfPoints())
    {
      error = fileName + ": cannot read: point array '" +
        (array->GetName() ? MessageText(array->GetName()) : std::string("(no name)")) + "' has " +
        std::to_string(array->GetNumberOfTuples()) + " values for " +
        std::to_string(points->GetNumberOfPoints()) + " points";
      return nullptr;
    }
  }
  vtkSmartPointer<vtkPointSet> result;
  result.TakeReference(points->NewInstance());
  result->ShallowCopy(points);
  return result;
}

namespace
{
double ReaderTimeLimitSeconds = 0.0;

// Writes all of `text` to `fd`.
void WriteAll(int fd, const std::string& text)
{
  for (size_t done = 0; done < text.size();)
  {
    const ssize_t n = ::write(fd, text.data() + done, text.size() - done);
    if (n <= 0 && errno != EINTR)
    {
      return;
    }
    done += n > 0 ? static_cast<size_t>(n) : 0;
  }
}
} // namespace

void vtkPointCloudIO::SetReaderTimeLimit(double seconds)
{
  ReaderTimeLimitSeconds = seconds > 0.0 ? seconds : 0.0;
}

double vtkPointCloudIO::GetReaderTimeLimit()
{
  return ReaderTimeLimitSeconds;
}

vtkSmartPointer<vtkPointSet> vtkPointCloudIO::ReadIsolated(const std::string& fileName,
  const std::string& extension, double fileSize, std::string& error, vtkCommand* observer)
{
  // VTK's readers crash or loop on some malformed files (a cut or corrupt legacy body, a huge
  // NumberOfComponents, a bad compressed block): they run in a child process under a time and a
  // memory limit, which hands the cloud back as a legacy binary VTK file in an anonymous memory
  // file (its own output, which the legacy reader reads safely), or its one-line error.
  const int memory = ::memfd_create("featurepoints-read", MFD_CLOEXEC);
  if (memory < 0)
  {
    return ReadWithReader(fileName, extension, error, observer);
  }
  const double limit =
    ReaderTimeLimitSeconds > 0.0 ? ReaderTimeLimitSeconds : 60.0 + fileSize / 4e6;
  // One read in a child process; its wait status, or -1 when no child could be started.
  auto readInChild = [&](const std::vector<std::pair<std::string, bool>>& leaveOut) -> int {
    std::fflush(nullptr);
    ::ftruncate(memory, 0);
    ::lseek(memory, 0, SEEK_SET);
    const pid_t pid = ::fork();
    if (pid < 0)
    {
      return -1;
    }
    if (pid == 0)
    {
      ::prctl(PR_SET_PDEATHSIG, SIGKILL); // ends with its parent (killed by a signal, say)
      std::signal(SIGALRM, SIG_DFL);
      const rlimit core = { 0, 0 };
      ::setrlimit(RLIMIT_CORE, &core);
  #ifndef FEATUREPOINTS_IO_SANITIZED
      // No more address space than the machine has memory: a huge declared count fails at once.
      // A legacy file is not compressed: what it holds takes a few times its size in memory, so
      // its reader gets 2 GiB plus 64 times the file's size at most (a 20 KB file that declares a
      // billion cells took all of 24 GB for a minute before failing).
      const long pages = ::sysconf(_SC_PHYS_PAGES), pageSize = ::sysconf(_SC_PAGESIZE);
      if (pages > 0 && pageSize > 0)
      {
        double bytes = static_cast<double>(pages) * static_cast<double>(pageSize);
        if (extension == "vtk")
        {
          // Beyond the address space this process already has from its parent (a host
          // application's threads and data: the limit counts them too).
          double current = 0.0;
          if (FILE* statm = std::fopen("/proc/self/statm", "r"))
          {
            unsigned long size = 0;
            if (std::fscanf(statm, "%lu", &size) == 1)
            {
              current = static_cast<double>(size) * static_cast<double>(pageSize);
            }
            std::fclose(statm);
          }
          bytes = std::min(bytes, current + 2147483648.0 + 64.0 * fileSize);
        }
        const rlimit space = { static_cast<rlim_t>(bytes), static_cast<rlim_t>(bytes) };
        ::setrlimit(RLIMIT_AS, &space);
      }
  #endif
      ::alarm(static_cast<unsigned>(std::min(limit, 1e6)));
      std::string childError;
      vtkSmartPointer<vtkPointSet> cloud;
      try
      {
        cloud = ReadWithReader(fileName, extension, childError, observer, leaveOut);
      }
      catch (const std::exception& e)
      {
        childError = WithFile(fileName, "cannot read: " + ExceptionText(e));
      }
      if (!cloud)
      {
        WriteAll(memory, childError);
        ::_exit(3);
      }
      vtkNew<vtkDataSetWriter> writer;
      writer->SetInputData(cloud);
      writer->SetFileTypeToBinary();
      const std::string path = "/proc/self/fd/" + std::to_string(memory);
      writer->SetFileName(path.c_str());
      ScopedCapture capture(false);
      try
      {
        if (writer->Write() != 1 || writer->GetErrorCode() != vtkErrorCode::NoError)
        {
          WriteAll(memory, fileName + ": cannot read: not enough memory to hand the cloud over");
          ::_exit(3);
        }
      }
      catch (const std::exception& e)
      {
        ::ftruncate(memory, 0);
        ::lseek(memory, 0, SEEK_SET);
        WriteAll(memory, WithFile(fileName, "cannot read: " + ExceptionText(e)));
        ::_exit(3);
      }
      ::_exit(0);
    }
    int status = 0;
    while (::waitpid(pid, &status, 0) < 0 && errno == EINTR)
    {
    }
    return status;
  };
  int status = readInChild({});
  if (status < 0)
  {
    ::close(memory);
    return ReadWithReader(fileName, extension, error, observer);
  }
  // VTK's XML readers crash on a String array of point or cell data that holds fewer or more
  // strings than its tuples call for: read again without the file's String arrays, and say so.
  std::vector<XMLStringArray> leftOut;
  if (WIFSIGNALED(status) && WTERMSIG(status) != SIGALRM && WTERMSIG(status) != SIGXCPU &&
    (extension == "vtp" || extension == "vtu"))
  {
    leftOut = XMLStringArrays(fileName);
    std::vector<std::pair<std::string, bool>> names;
    for (const XMLStringArray& array : leftOut)
    {
      names.emplace_back(array.Name, array.Cells);
    }
    const int again = names.empty() ? -1 : readInChild(names);
    if (again >= 0 && WIFEXITED(again) && WEXITSTATUS(again) == 0)
    {
      for (const XMLStringArray& array : leftOut)
      {
        vtkGenericWarningMacro(<< fileName << ": " << (array.Cells ? "cell" : "point")
                               << " array " << QuotedWord(array.Name)
                               << " (type String) left out: VTK's reader crashes on "
                               << (leftOut.size() == 1 ? "it" : "the file's String arrays")
                               << " (" << strsignal(WTERMSIG(status)) << "; "
                               << (array.Holds.empty()
                                      ? "other strings than its tuples and components call "
                                        "for, or corrupt data"
                                      : "it holds " + array.Holds)
                               << "); the cloud is read without "
                               << (leftOut.size() == 1 ? "it" : "them"));
      }
      status = again;
    }
    else if (again >= 0 && WIFEXITED(again))
    {
      status = again; // the reader's own error without those arrays: the file's first problem
    }
  }
  auto readText = [memory]() {
    std::string text;
    char buffer[4096];
    ::lseek(memory, 0, SEEK_SET);
    for (ssize_t n; (n = ::read(memory, buffer, sizeof(buffer))) > 0 && text.size() < 65536;)
    {
      text.append(buffer, static_cast<size_t>(n));
    }
    return text;
  };
  vtkSmartPointer<vtkPointSet> result;
  if (WIFSIGNALED(status))
  {
    const int signal = WTERMSIG(status);
    std::ostringstream m;
    if (signal == SIGALRM || signal == SIGXCPU)
    {
      m << fileName << ": cannot read: VTK's reader did not finish within " << limit
        << " s: the file is malformed (or larger than it looks)";
    }
    else
    {
      m << fileName << ": cannot read: VTK's reader failed on the file (" << strsignal(signal)
        << "): the file is malformed";
    }
    // A legacy file's lying counts make VTK's reader crash or run out of time: named instead.
    const std::string legacy = extension == "vtk" ? LegacyProblem(fileName) : std::string();
    error = legacy.empty() ? m.str() : legacy;
  }
  else if (!WIFEXITED(status) || WEXITSTATUS(status) != 0)
  {
    error = readText();
    if (error.empty())
    {
      error = fileName + ": cannot read: VTK's reader failed on the file";
    }
  }
  else
  {
    vtkNew<vtkDataSetReader> reader;
    const std::string path = "/proc/self/fd/" + std::to_string(memory);
    reader->SetFileName(path.c_str());
    reader->ReadAllScalarsOn();
    reader->ReadAllVectorsOn();
    reader->ReadAllNormalsOn();
    reader->ReadAllTensorsOn();
    reader->ReadAllColorScalarsOn();
    reader->ReadAllTCoordsOn();
    reader->ReadAllFieldsOn();
    ScopedCapture capture(false);
    try
    {
      reader->Update();
      result = vtkPointSet::SafeDownCast(reader->GetOutput());
    }
    catch (const std::exception& e)
    {
      result = nullptr;
      capture.Window->Message = ExceptionText(e);
    }
    if (!result || !capture.Window->Text().empty())
    {
      error = fileName + ": cannot read: " +
        (capture.Window->Text().empty() ? std::string("the reader's output was lost")
                                        : capture.Window->Text());
      result = nullptr;
    }
    else
    {
      vtkSmartPointer<vtkPointSet> copy;
      copy.TakeReference(result->NewInstance());
      copy->ShallowCopy(result);
      result = copy;
    }
  }
  ::close(memory);
  return result;
}

std::string vtkPointCloudIO::WriteTarget(const std::string& fileName)
{
  struct stat info;
  if (::lstat(fileName.c_str(), &info) != 0 || !S_ISLNK(info.st_mode))
  {
    return fileName;
  }
  std::string error;
  const std::string real = vtksys::SystemTools::GetRealPath(fileName, &error);
  if (!real.empty() && error.empty())
  {
    return real;
  }
  // A link to a file not there yet (a dangling link): written through too, as a link to an
  // existing file is, at the end of its chain (relative targets from the link's folder; at
  // most 40 links, as the kernel follows).
  std::string target = fileName;
  for (int hop = 0; hop < 40 && ::lstat(target.c_str(), &info) == 0 && S_ISLNK(info.st_mode); ++hop)
  {
    std::vector<char> buffer(static_cast<size_t>(info.st_size > 0 ? info.st_size : 4096) + 1);
    const ssize_t length = ::readlink(target.c_str(), buffer.data(), buffer.size() - 1);
    if (length <= 0)
    {
      return fileName;
    }
    const std::string next(buffer.data(), static_cast<size_t>(length));
    const size_t slash = target.find_last_of('/');
    target = next[0] == '/' || slash == std::string::npos ? next : target.substr(0, slash + 1) + next;
  }
  return ::lstat(target.c_str(), &info) != 0 ? target : fileName;
}

std::string vtkPointCloudIO::CreateTemporaryFile(
  const std::string& fileName, std::string& error, bool removeOnSignal)
{
  const size_t slash = fileName.find_last_of('/');
  const std::string folder = slash == std::string::npos ? "." : fileName.substr(0, slash + 1);
  const std::string base = slash == std::string::npos ? fileName : fileName.substr(slash + 1);
  // ".BASE.XXXXXX" adds 8 bytes to the name: a target name within 8 bytes of the longest a
  // folder takes (NAME_MAX, 255 here) gets a short temporary name instead.
  const long longest = ::pathconf(folder.c_str(), _PC_NAME_MAX);
  const bool shortName = base.size() + 8 > static_cast<size_t>(longest > 0 ? longest : 255);
  const std::string prefix =
    (folder == "." ? std::string("./") : folder) + (shortName ? ".featurepoints." : "." + base + ".");
  for (int attempt = 0; attempt < 100; ++attempt)
  {
    const std::string name = TemporaryName(prefix);
    const int slot = removeOnSignal ? RegisterTemporary(name) : -1;
    // Created with the permissions of any new file (0666 less the umask). POSIX open(): O_EXCL
    // creates the file only if no other writer has, which no vtksys or stream call guarantees.
    const int fd = ::open(name.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, 0666);
    if (fd >= 0)
    {
      ::close(fd);
      return name;
    }
    const int cause = errno;
    ReleaseTemporary(slot);
    if (cause != EEXIST)
    {
      error = fileName + ": cannot create a file in " +
        (folder == "." ? "the current folder" : folder) + ": " + std::strerror(cause);
      return "";
    }
  }
  error = fileName + ": cannot create a file in " +
    (folder == "." ? "the current folder" : folder) + ": no free temporary name";
  return "";
}

void vtkPointCloudIO::ReleaseTemporaryFile(const std::string& temporary)
{
  for (TemporarySlot& slot : TemporarySlots)
  {
    if (slot.State.load() == Named && temporary == slot.Name)
    {
      slot.State.store(Free);
      return;
    }
  }
}

namespace
{
// `poly` with every array renamed by `rename` (see WithXMLNames()).
vtkSmartPointer<vtkPolyData> WithNames(
  vtkPolyData* poly, const std::function<std::string(const char*)>& rename)
{
  vtkFieldData* sources[3] = { poly->GetPointData(), poly->GetCellData(), poly->GetFieldData() };
  bool needed = false;
  for (vtkFieldData* fd : sources)
  {
    for (int i = 0; i < fd->GetNumberOfArrays() && !needed; ++i)
    {
      const char* name = fd->GetAbstractArray(i) ? fd->GetAbstractArray(i)->GetName() : "";
      needed = rename(name) != (name ? name : "");
    }
  }
  if (!needed)
  {
    return poly;
  }
  auto copy = vtkSmartPointer<vtkPolyData>::New();
  copy->ShallowCopy(poly);
  vtkFieldData* targets[3] = { copy->GetPointData(), copy->GetCellData(), copy->GetFieldData() };
  for (int f = 0; f < 3; ++f)
  {
    vtkFieldData* from = sources[f];
    vtkFieldData* to = targets[f];
    auto* attributes = vtkDataSetAttributes::SafeDownCast(from);
    to->Initialize();
    for (int i = 0; i < from->GetNumberOfArrays(); ++i)
    {
      vtkAbstractArray* a = from->GetAbstractArray(i);
      std::string name = rename(a->GetName());
      // AddArray replaces an array of the same name: a renamed one that meets another gets
      // "_2", "_3", ...
      const std::string base = name;
      for (int suffix = 2; name != (a->GetName() ? a->GetName() : "") &&
           (to->GetAbstractArray(name.c_str()) || from->GetAbstractArray(name.c_str()));
           ++suffix)
      {
        name = base + "_" + std::to_string(suffix);
      }
      vtkSmartPointer<vtkAbstractArray> b = a;
      if (name != (a->GetName() ? a->GetName() : ""))
      {
        b.TakeReference(a->NewInstance());
        if (auto* values = vtkDataArray::SafeDownCast(a))
        {
          vtkDataArray::SafeDownCast(b)->ShallowCopy(values);
        }
        else
        {
          b->DeepCopy(a);
        }
        b->SetName(name.c_str());
      }
      to->AddArray(b);
      const int attribute = attributes ? attributes->IsArrayAnAttribute(i) : -1;
      if (attribute >= 0)
      {
        vtkDataSetAttributes::SafeDownCast(to)->SetActiveAttribute(i, attribute);
      }
    }
  }
  return copy;
}
} // namespace

vtkSmartPointer<vtkPolyData> vtkPointCloudIO::WithXMLNames(
  vtkPolyData* poly, const std::string& fileName)
{
  vtkSmartPointer<vtkPolyData> named = WithNames(poly, XMLName);
  // A string holding a NUL byte: VTK's XML writer writes it as it is, and its reader, which ends
  // each string at a NUL, then reads more strings than the array has values and crashes.
  static const char* const kinds[3] = { "point", "cell", "field" };
  vtkSmartPointer<vtkPolyData> copy;
  for (int f = 0; f < 3; ++f)
  {
    vtkFieldData* fd = f == 0 ? named->GetPointData()
      : f == 1                ? static_cast<vtkFieldData*>(named->GetCellData())
                              : named->GetFieldData();
    for (int i = 0; i < fd->GetNumberOfArrays(); ++i)
    {
      auto* strings = vtkStringArray::SafeDownCast(fd->GetAbstractArray(i));
      vtkIdType at = -1;
      for (vtkIdType v = 0; strings && at < 0 && v < strings->GetNumberOfValues(); ++v)
      {
        at = strings->GetValue(v).find('\0') != std::string::npos ? v : -1;
      }
      if (at < 0)
      {
        continue;
      }
      if (!copy)
      {
        copy = vtkSmartPointer<vtkPolyData>::New();
        copy->ShallowCopy(named);
      }
      const std::string name = strings->GetName() ? strings->GetName() : "";
      vtkGenericWarningMacro(<< (fileName.empty() ? std::string() : fileName + ": ") << kinds[f]
                             << " array " << QuotedWord(name)
                             << " (type String) left out: its value " << at
                             << " (counting from 0) holds a NUL byte, which a VTK XML file "
                                "cannot hold (VTK's reader crashes on such a file)");
      vtkFieldData* target = f == 0 ? copy->GetPointData()
        : f == 1                    ? static_cast<vtkFieldData*>(copy->GetCellData())
                                    : copy->GetFieldData();
      target->RemoveArray(name.c_str());
    }
  }
  return copy ? copy : named;
}

namespace
{
// Whether `target` (a write target: links resolved) is something other than a regular file that
// exists (a device, a pipe, a socket): the writers write a temporary file and rename it over the
// target, which would replace such a thing with a file.
bool NotRegularFile(const std::string& fileName, const std::string& target, std::string& error)
{
  struct stat info;
  if (::stat(target.c_str(), &info) == 0 && !S_ISREG(info.st_mode) && !S_ISDIR(info.st_mode))
  {
    error = fileName + ": is not a regular file (a device, a pipe or a socket): outputs are "
                       "written to files only";
    return true;
  }
  return false;
}
} // namespace

bool vtkPointCloudIO::CanCreate(const std::string& fileName, std::string& error)
{
  if (vtksys::SystemTools::FileIsDirectory(fileName))
  {
    error = fileName + ": is a folder, not a file";
    return false;
  }
  if (NotRegularFile(fileName, WriteTarget(fileName), error))
  {
    return false;
  }
  const std::string temporary = CreateTemporaryFile(WriteTarget(fileName), error);
  if (temporary.empty())
  {
    return false;
  }
  vtksys::SystemTools::RemoveFile(temporary);
  return true;
}

bool vtkPointCloudIO::Write(vtkPointSet* data, const std::string& fileName, std::string& error,
  const std::string& extensionIn, vtkCommand* observer)
{
  error.clear();
  const std::string extension = extensionIn.empty() ? GetExtension(fileName) : extensionIn;
  if (!data)
  {
    error = fileName + ": nothing to write";
    return false;
  }
  if (!CanWrite(extension))
  {
    error = fileName + ": cannot write the format of the extension " +
      (extension.empty() ? std::string("(none)") : "'." + extension + "'") +
      "; writable: " + GetWritableExtensions();
    return false;
  }
  // Known to the signal handlers from before it exists (see RemoveTemporaryFileInProgress).
  const std::string target = WriteTarget(fileName);
  if (NotRegularFile(fileName, target, error))
  {
    return false;
  }
  const std::string temporary = CreateTemporaryFile(target, error, true);
  if (temporary.empty())
  {
    return false;
  }

  // vtkXMLWriter is not a vtkWriter: keep the algorithm and its Write().
  vtkSmartPointer<vtkAlgorithm> writer;
  std::function<int()> write;
  if (extension == "vtp")
  {
    auto w = vtkSmartPointer<vtkXMLPolyDataWriter>::New();
    w->SetInputData(WithXMLNames(AsPolyData(data), fileName));
    w->SetFileName(temporary.c_str());
    // Raw appended data compressed with LZ4: on a 1,000,000-point result with its arrays, 0.07 s
    // and 45 MB, where VTK's default (base64, zlib) takes 2.6 s and 48 MB. VTK 8.1 and later,
    // ParaView 5.5 and later read it.
    w->SetDataModeToAppended();
    w->EncodeAppendedDataOff();
    w->SetCompressorTypeToLZ4();
    writer = w;
    write = [w]() { return w->Write(); };
  }
  else if (extension == "vtk")
  {
    auto w = vtkSmartPointer<vtkPolyDataWriter>::New();
    w->SetInputData(WithNames(AsPolyData(data), LegacyName));
    w->SetFileName(temporary.c_str());
    w->SetFileTypeToBinary();
    writer = w;
    write = [w]() { return w->Write(); };
  }
  else if (extension == "pcd")
  {
    auto w = vtkSmartPointer<vtkPointCloudPCDWriter>::New();
    w->SetInputData(data);
    w->SetFileName(temporary.c_str());
    writer = w;
    write = [w]() { return w->Write(); };
  }
  else if (extension == "ply")
  {
    auto w = vtkSmartPointer<vtkPointCloudPLYWriter>::New();
    w->SetInputData(data);
    w->SetFileName(temporary.c_str());
    writer = w;
    write = [w]() { return w->Write(); };
  }
  else
  {
    auto w = vtkSmartPointer<vtkPointCloudTextWriter>::New();
    w->SetInputData(data);
    w->SetFileName(temporary.c_str());
    writer = w;
    write = [w]() { return w->Write(); };
  }
  ScopedCapture capture(false);
  capture.Window->Temporary = temporary;
  capture.Window->Target = fileName;
  vtkNew<ErrorCatcher> catcher;
  catcher->First = &capture.Window->Message;
  catcher->Pipeline = &capture.Window->PipelineMessage;
  writer->AddObserver(vtkCommand::ErrorEvent, catcher);
  if (observer)
  {
    writer->AddObserver(vtkCommand::ProgressEvent, observer);
  }
  int written = 0;
  std::string thrown;
  try
  {
    written = write();
  }
  catch (const std::exception& e)
  {
    thrown = "cannot write: " + ExceptionText(e);
  }
  const unsigned long code = writer->GetErrorCode();
  bool ok = written == 1 && capture.Window->Text().empty() && thrown.empty() &&
    code == vtkErrorCode::NoError;
  if (!ok)
  {
    // The cause, else the error code (the writers' own words for a full disk), else the
    // executive's report.
    std::string message = !thrown.empty() ? thrown
      : !capture.Window->Message.empty() ? capture.Window->Message
      : code == vtkErrorCode::OutOfDiskSpaceError
      ? std::string("cannot write: out of disk space (or past the file size limit)")
      : code != vtkErrorCode::NoError
      ? std::string("cannot write: ") + vtkErrorCode::GetStringFromErrorCode(code)
      : capture.Window->PipelineMessage;
    // The writers name the temporary file; the user knows the target (as in the warnings).
    message = capture.Window->Passed(message.c_str());
    error = WithFile(fileName,
      message.empty() ? std::string("cannot write: ") +
          vtkErrorCode::GetStringFromErrorCode(writer->GetErrorCode())
                      : message);
  }
  else
  {
    // A file replaced keeps its permissions (a new one gets those of any new file).
    struct stat info;
    if (::stat(target.c_str(), &info) == 0 && S_ISREG(info.st_mode))
    {
      ::chmod(temporary.c_str(), info.st_mode & 07777);
    }
    if (std::rename(temporary.c_str(), target.c_str()) != 0)
    {
      error = fileName + ": cannot replace the file: " + std::strerror(errno);
      ok = false;
    }
  }
  if (!ok)
  {
    vtksys::SystemTools::RemoveFile(temporary);
  }
  ReleaseTemporaryFile(temporary);
  return ok;
}

void vtkPointCloudIO::RemoveTemporaryFileInProgress()
{
  for (TemporarySlot& slot : TemporarySlots)
  {
    if (slot.State.load() == Named)
    {
      // unlink() is async-signal-safe; vtksys::SystemTools::RemoveFile() allocates a string.
      ::unlink(slot.Name);
    }
  }
}
