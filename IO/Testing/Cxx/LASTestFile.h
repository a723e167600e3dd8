// LAS files for the tests, written byte by byte from the LAS specification's tables (public
// header block of LAS 1.2, 1.3 and 1.4, a variable-length record, point data record formats 0 to
// 10, extra bytes). Little-endian hosts only.
#ifndef LASTestFile_h
#define LASTestFile_h

#include <algorithm>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <string>
#include <vector>

namespace featurepoints
{
namespace lastest
{
// Appends the little-endian bytes of a value (the tests run on little-endian hosts: see main).
template <typename T>
inline void Put(std::string& out, T value)
{
  char bytes[sizeof(T)];
  std::memcpy(bytes, &value, sizeof(T));
  out.append(bytes, sizeof(T));
}

inline void PutText(std::string& out, const char* text, size_t size)
{
  std::string field(size, '\0');
  std::memcpy(&field[0], text, std::min(size, std::strlen(text)));
  out += field;
}

// One point as the formats store it.
struct Point
{
  int32_t X, Y, Z;
  uint16_t Intensity;
  int ReturnNumber, NumberOfReturns;
  int Classification;
  double GpsTime;
  uint16_t Red, Green, Blue, Nir;
};

struct File
{
  int Minor = 2;
  int Format = 0;
  int ExtraBytes = 0; // after each standard record
  bool Vlr = false;   // one variable-length record between header and points
  double Scale[3] = { 0.01, 0.01, 0.01 };
  double Offset[3] = { 0, 0, 0 };
  uint64_t DeclaredPoints = ~uint64_t(0); // the header's count (default: the points')
  int FormatByte = -1;                    // the header's format byte (default: Format)
  int HeaderSize = -1;                    // the header's size field (default: the version's)
  int RecordLength = -1;                  // the header's record length (default: the true one)
  std::vector<Point> Points;
};

inline size_t StandardRecordLength(int format)
{
  const size_t sizes[] = { 20, 28, 26, 34, 57, 63, 30, 36, 38, 59, 67 };
  return sizes[format];
}

// A wave packet (formats 4, 5, 9, 10): descriptor index, byte offset, size, location, Xt Yt Zt.
inline void PutWavePacket(std::string& out)
{
  Put<uint8_t>(out, 1);
  Put<uint64_t>(out, 123456789);
  Put<uint32_t>(out, 512);
  Put<float>(out, 1.5f);
  Put<float>(out, 0.1f);
  Put<float>(out, 0.2f);
  Put<float>(out, 0.3f);
}

inline std::string Record(const Point& p, int format)
{
  std::string out;
  Put<int32_t>(out, p.X);
  Put<int32_t>(out, p.Y);
  Put<int32_t>(out, p.Z);
  Put<uint16_t>(out, p.Intensity);
  const bool gps = format == 1 || format >= 3;
  const bool rgb =
    format == 2 || format == 3 || format == 5 || format == 7 || format == 8 || format == 10;
  if (format <= 5)
  {
    // return number (3 bits), number of returns (3 bits), scan direction, edge of flight line
    Put<uint8_t>(out, static_cast<uint8_t>(p.ReturnNumber | p.NumberOfReturns << 3 | 1 << 7));
    // classification (5 bits), synthetic, key-point, withheld: the flags set, to be dropped
    Put<uint8_t>(out, static_cast<uint8_t>(p.Classification | 0xE0));
    Put<int8_t>(out, -12);    // scan angle rank
    Put<uint8_t>(out, 77);    // user data
    Put<uint16_t>(out, 4321); // point source ID
    if (gps)
    {
      Put<double>(out, p.GpsTime);
    }
    if (rgb)
    {
      Put<uint16_t>(out, p.Red);
      Put<uint16_t>(out, p.Green);
      Put<uint16_t>(out, p.Blue);
    }
    if (format == 4 || format == 5)
    {
      PutWavePacket(out);
    }
  }
  else
  {
    // return number (4 bits), number of returns (4 bits)
    Put<uint8_t>(out, static_cast<uint8_t>(p.ReturnNumber | p.NumberOfReturns << 4));
    // classification flags (4), scanner channel (2), scan direction, edge of flight line
    Put<uint8_t>(out, 0xFF);
    Put<uint8_t>(out, static_cast<uint8_t>(p.Classification)); // a whole byte
    Put<uint8_t>(out, 77);                                     // user data
    Put<int16_t>(out, -2000);                                  // scan angle
    Put<uint16_t>(out, 4321);                                  // point source ID
    Put<double>(out, p.GpsTime);
    if (rgb)
    {
      Put<uint16_t>(out, p.Red);
      Put<uint16_t>(out, p.Green);
      Put<uint16_t>(out, p.Blue);
    }
    if (format == 8 || format == 10)
    {
      Put<uint16_t>(out, p.Nir);
    }
    if (format == 9 || format == 10)
    {
      PutWavePacket(out);
    }
  }
  return out;
}

// The whole file, field by field as the specification's public header block lists them.
inline std::string Bytes(const File& f)
{
  const size_t headerSize = f.Minor >= 4 ? 375 : (f.Minor == 3 ? 235 : 227);
  const size_t recordLength = StandardRecordLength(f.Format) + f.ExtraBytes;
  std::string vlr;
  if (f.Vlr)
  {
    Put<uint16_t>(vlr, 0);               // reserved
    PutText(vlr, "LASF_Projection", 16); // user ID
    Put<uint16_t>(vlr, 2112);            // record ID (OGC WKT)
    Put<uint16_t>(vlr, 10);              // record length after header
    PutText(vlr, "a WKT stand-in", 32);  // description
    PutText(vlr, "LOCAL_CS[]", 10);      // the record itself
  }
  const uint64_t count = f.DeclaredPoints != ~uint64_t(0) ? f.DeclaredPoints : f.Points.size();
  std::string h;
  PutText(h, "LASF", 4);
  Put<uint16_t>(h, 7);                       // file source ID
  Put<uint16_t>(h, f.Minor >= 4 ? 0x11 : 0); // global encoding
  Put<uint32_t>(h, 0);                       // project ID GUID data 1
  Put<uint16_t>(h, 0);                       // data 2
  Put<uint16_t>(h, 0);                       // data 3
  PutText(h, "", 8);                         // data 4
  Put<uint8_t>(h, 1);                        // version major
  Put<uint8_t>(h, static_cast<uint8_t>(f.Minor));
  PutText(h, "FeaturePoints test", 32); // system identifier
  PutText(h, "byte by byte", 32);       // generating software
  Put<uint16_t>(h, 123);                // creation day of year
  Put<uint16_t>(h, 2024);               // creation year
  Put<uint16_t>(h, static_cast<uint16_t>(f.HeaderSize >= 0 ? f.HeaderSize : headerSize));
  Put<uint32_t>(h, static_cast<uint32_t>(headerSize + vlr.size())); // offset to point data
  Put<uint32_t>(h, f.Vlr ? 1 : 0);                                  // number of VLRs
  Put<uint8_t>(h, static_cast<uint8_t>(f.FormatByte >= 0 ? f.FormatByte : f.Format));
  Put<uint16_t>(h, static_cast<uint16_t>(f.RecordLength >= 0 ? f.RecordLength : recordLength));
  // legacy number of point records: 0 in LAS 1.4 for formats 6-10, as the specification asks
  Put<uint32_t>(h, f.Minor >= 4 && f.Format >= 6 ? 0 : static_cast<uint32_t>(count));
  for (int r = 0; r < 5; ++r)
  {
    Put<uint32_t>(h, 0); // legacy number of points by return
  }
  for (int c = 0; c < 3; ++c)
  {
    Put<double>(h, f.Scale[c]);
  }
  for (int c = 0; c < 3; ++c)
  {
    Put<double>(h, f.Offset[c]);
  }
  for (int c = 0; c < 6; ++c)
  {
    Put<double>(h, 0.0); // max x, min x, max y, min y, max z, min z
  }
  if (f.Minor >= 3)
  {
    Put<uint64_t>(h, 0); // start of waveform data packet record
  }
  if (f.Minor >= 4)
  {
    Put<uint64_t>(h, 0); // start of first extended VLR
    Put<uint32_t>(h, 0); // number of extended VLRs
    Put<uint64_t>(h, count);
    for (int r = 0; r < 15; ++r)
    {
      Put<uint64_t>(h, 0); // number of points by return
    }
  }
  if (h.size() != headerSize)
  {
    std::printf("FAILED: the test's header has %zu bytes, not %zu\n", h.size(), headerSize);
    std::abort();
  }
  std::string out = h + vlr;
  for (const Point& p : f.Points)
  {
    out += Record(p, f.Format) + std::string(static_cast<size_t>(f.ExtraBytes), '\xAB');
  }
  return out;
}

} // namespace lastest
} // namespace featurepoints

#endif
