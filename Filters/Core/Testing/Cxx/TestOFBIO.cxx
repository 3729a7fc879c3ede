// File I/O: exact round trips, and a clear error with an empty output on every bad file.
#include "vtkOFBIOTestHelpers.h"

#include "vtkIdTypeArray.h"
#include "vtkMinimalStandardRandomSequence.h"
#include "vtkSOADataArrayTemplate.h"
#include "vtkTimerLog.h"

#include <algorithm>
#include <limits>
#include <sstream>

using namespace vtkofbtest;

TEST(IO, CRC32KnownValue)
{
  EXPECT_EQ(vtkOFBWriter::UpdateCRC32(0, "123456789", 9), 0xCBF43926u);
  const unsigned int part = vtkOFBWriter::UpdateCRC32(0, "1234", 4);
  EXPECT_EQ(vtkOFBWriter::UpdateCRC32(part, "56789", 5), 0xCBF43926u);
  EXPECT_EQ(vtkOFBWriter::UpdateCRC32(0, "", 0), 0u);
}

TEST(IO, RoundTripBunnyIsExact)
{
  vtkSmartPointer<vtkPolyData> bunny = ReadMesh("stanford-bunny.obj");
  ASSERT_TRUE(bunny);
  AddPointArrays(bunny);
  vtkSmartPointer<vtkOFB> ofb = Build(bunny, 256);
  ASSERT_GT(ofb->GetNumberOfSamples(), 10000);
  vtkPointData* sd = ofb->GetSampleData();
  ASSERT_TRUE(sd->GetArray("Pressure"));
  ASSERT_TRUE(sd->GetArray("Label"));
  EXPECT_EQ(sd->GetArray("Pressure")->GetDataType(), VTK_DOUBLE);
  EXPECT_EQ(sd->GetArray("Label")->GetDataType(), VTK_INT);
  EXPECT_TRUE(sd->GetScalars() && sd->GetScalars()->GetDataType() == VTK_UNSIGNED_CHAR);
  EXPECT_TRUE(sd->GetNormals());
  EXPECT_TRUE(sd->GetVectors());
  EXPECT_TRUE(sd->GetTCoords());

  TempDirectory dir;
  const std::string path = dir.File("bunny.ofb");
  vtkNew<ProgressCounter> writeProgress;
  int result = 0;
  EXPECT_EQ(WriteOFB(ofb, path, &result, writeProgress), "");
  EXPECT_EQ(result, 1);
  EXPECT_GT(writeProgress->Count, 2);
  EXPECT_EQ(writeProgress->Last, 1.0);
  EXPECT_TRUE(vtkOFBReader::CanReadFile(path.c_str()));

  std::string errors;
  vtkNew<ProgressCounter> readProgress;
  vtkSmartPointer<vtkOFB> back = ReadOFB(path, errors, readProgress);
  EXPECT_EQ(errors, "");
  EXPECT_GT(readProgress->Count, 2);
  EXPECT_EQ(readProgress->Last, 1.0);
  ExpectSameOFB(ofb, back);
  EXPECT_EQ(dir.List(), std::vector<std::string>{ "bunny.ofb" });

  // Queries on the copy answer like the original.
  for (vtkIdType id = 0; id < ofb->GetNumberOfSamples(); id += 4099)
  {
    double x[3];
    ASSERT_TRUE(back->GetSamplePosition(id, x));
    EXPECT_EQ(back->FindClosestSample(x), ofb->FindClosestSample(x));
  }
}

TEST(IO, RoundTripEveryNumericTypeAndRole)
{
  vtkSmartPointer<vtkOFB> ofb = SmallOFB();
  const vtkIdType n = ofb->GetNumberOfSamples();
  ASSERT_GT(n, 100);
  vtkPointData* sd = ofb->GetSampleData();
  const int types[] = { VTK_CHAR,
    VTK_SIGNED_CHAR,
    VTK_UNSIGNED_CHAR,
    VTK_SHORT,
    VTK_UNSIGNED_SHORT,
    VTK_INT,
    VTK_UNSIGNED_INT,
    VTK_LONG,
    VTK_UNSIGNED_LONG,
    VTK_LONG_LONG,
    VTK_UNSIGNED_LONG_LONG,
    VTK_FLOAT,
    VTK_DOUBLE,
    VTK_ID_TYPE };
  vtkNew<vtkMinimalStandardRandomSequence> random;
  for (const int type : types)
  {
    auto array = vtkSmartPointer<vtkDataArray>::Take(vtkDataArray::CreateDataArray(type));
    array->SetName((std::string("Random ") + array->GetDataTypeAsString()).c_str());
    array->SetNumberOfComponents(1 + type % 4);
    array->SetNumberOfTuples(n);
    // Random bits: NaNs, infinities, denormals and negative zeros must survive.
    unsigned char* p = static_cast<unsigned char*>(array->GetVoidPointer(0));
    for (vtkIdType i = 0; i < array->GetNumberOfValues() * array->GetDataTypeSize(); ++i)
    {
      random->Next();
      p[i] = static_cast<unsigned char>(random->GetValue() * 256.0);
    }
    sd->AddArray(array);
  }
  // A tensor (9 components), a non-contiguous (SOA) array and an unnamed array.
  vtkNew<vtkDoubleArray> tensor;
  tensor->SetName("Stress");
  tensor->SetNumberOfComponents(9);
  tensor->SetNumberOfTuples(n);
  tensor->Fill(0.5);
  sd->SetTensors(tensor);
  vtkNew<vtkSOADataArrayTemplate<float>> soa;
  soa->SetName("SOA");
  soa->SetNumberOfComponents(3);
  soa->SetNumberOfTuples(n);
  for (vtkIdType i = 0; i < n; ++i)
  {
    soa->SetTuple3(i, i, -i, 0.5 * i);
  }
  sd->AddArray(soa);
  vtkNew<vtkIdTypeArray> unnamed;
  unnamed->SetNumberOfTuples(n);
  unnamed->Fill(-7);
  sd->AddArray(unnamed);

  TempDirectory dir;
  const std::string path = dir.File("types.ofb");
  ASSERT_EQ(WriteOFB(ofb, path), "");
  std::string errors;
  vtkSmartPointer<vtkOFB> back = ReadOFB(path, errors);
  EXPECT_EQ(errors, "");
  ExpectSameOFB(ofb, back);
  EXPECT_EQ(back->GetSampleData()->GetTensors(), back->GetSampleData()->GetArray("Stress"));
}

TEST(IO, EmptyRoundTrip)
{
  vtkNew<vtkOFB> empty;
  TempDirectory dir;
  const std::string path = dir.File("empty.ofb");
  int result = 0;
  EXPECT_EQ(WriteOFB(empty, path, &result), "");
  EXPECT_EQ(result, 1);
  const Bytes bytes = Load(path);
  EXPECT_EQ(bytes.size(), static_cast<size_t>(vtkOFBWriter::HeaderSize + 8 + 4 + 8));
  std::string errors;
  vtkSmartPointer<vtkOFB> back = ReadOFB(path, errors);
  EXPECT_EQ(errors, "");
  EXPECT_EQ(back->GetNumberOfSamples(), 0);
  EXPECT_EQ(back->GetNumberOfCells(), 0);
  EXPECT_EQ(back->GetCellSize(), 0.0);
  ExpectSameOFB(empty, back);
  const double origin[3] = { 0.0, 0.0, 0.0 };
  EXPECT_EQ(back->FindClosestSample(origin), -1);

  // Every prefix of the empty file is a truncated file.
  for (size_t size = 0; size < bytes.size(); ++size)
  {
    Save(path, bytes, size);
    ExpectReadError(path, size == 0 ? "empty" : "");
  }
}

TEST(IO, TruncatedFiles)
{
  vtkSmartPointer<vtkOFB> ofb = SmallOFB();
  TempDirectory dir;
  const std::string good = dir.File("good.ofb");
  const std::string bad = dir.File("bad.ofb");
  ASSERT_EQ(WriteOFB(ofb, good), "");
  const Bytes bytes = Load(good);
  const size_t arrays = FirstArrayOffset(bytes);
  std::vector<size_t> sizes = { 0,
    1,
    7,
    8,
    9,
    50,
    95,
    96,
    97,
    100,
    arrays - 4,
    arrays,
    arrays + 3,
    arrays + 40,
    bytes.size() / 2,
    bytes.size() - 9,
    bytes.size() - 8,
    bytes.size() - 1 };
  for (size_t size = 101; size < bytes.size(); size += 1009)
  {
    sizes.push_back(size);
  }
  for (const size_t size : sizes)
  {
    SCOPED_TRACE("truncated to " + std::to_string(size) + " of " + std::to_string(bytes.size()));
    Save(bad, bytes, size);
    ExpectReadError(bad, size == 0 ? "empty" : "");
  }
  // Trailing bytes are rejected too.
  Bytes longer = bytes;
  longer.push_back(0);
  Save(bad, longer, longer.size());
  ExpectReadError(bad, "unexpected bytes");
}

TEST(IO, EveryBitFlipIsDetected)
{
  vtkSmartPointer<vtkOFB> ofb = SmallOFB();
  TempDirectory dir;
  const std::string good = dir.File("good.ofb");
  const std::string bad = dir.File("bad.ofb");
  ASSERT_EQ(WriteOFB(ofb, good), "");
  const Bytes bytes = Load(good);
  std::vector<size_t> positions;
  for (size_t p = 0; p < bytes.size(); ++p)
  {
    // The header and the first array header in full, every 997th byte, the end in full.
    const size_t arrays = FirstArrayOffset(bytes);
    if (p < 160 || (p >= arrays && p < arrays + 48) || p % 997 == 0 || p + 48 > bytes.size())
    {
      positions.push_back(p);
    }
  }
  for (const size_t p : positions)
  {
    SCOPED_TRACE("bit flip at byte " + std::to_string(p));
    Bytes flipped = bytes;
    flipped[p] ^= static_cast<unsigned char>(1u << (p * 5 % 8));
    Save(bad, flipped, flipped.size());
    ExpectReadError(bad);
  }
  // The intact file still reads.
  std::string errors;
  ReadOFB(good, errors);
  EXPECT_EQ(errors, "");
}

TEST(IO, ForeignMissingAndUnnamedFiles)
{
  TempDirectory dir;
  // A PNG signature and header, and a Wavefront .obj.
  const Bytes png = { 0x89,
    'P',
    'N',
    'G',
    '\r',
    '\n',
    0x1a,
    '\n',
    0,
    0,
    0,
    13,
    'I',
    'H',
    'D',
    'R',
    0,
    0,
    0,
    1,
    0,
    0,
    0,
    1,
    8,
    6,
    0,
    0,
    0 };
  Save(dir.File("image.png"), png, png.size());
  ExpectReadError(dir.File("image.png"), "not an OFB file");
  EXPECT_FALSE(vtkOFBReader::CanReadFile(dir.File("image.png").c_str()));
  ExpectReadError(DataPath("stanford-bunny.obj"), "not an OFB file");
  EXPECT_FALSE(vtkOFBReader::CanReadFile(DataPath("stanford-bunny.obj").c_str()));
  // A short text file.
  const Bytes text = { 'h', 'i', '\n' };
  Save(dir.File("hi.txt"), text, text.size());
  ExpectReadError(dir.File("hi.txt"), "not an OFB file");
  // Missing file, a directory, no file name.
  ExpectReadError(dir.File("missing.ofb"), "does not exist");
  ExpectReadError(dir.Path, "directory");
  ExpectReadError("", "FileName");
  // The error names the file.
  ExpectReadError(dir.File("missing.ofb"), dir.File("missing.ofb"));

  // A reader whose previous read succeeded gives an empty output on a bad file.
  const std::string good = dir.File("good.ofb");
  ASSERT_EQ(WriteOFB(SmallOFB(), good), "");
  vtkNew<vtkOFBReader> reader;
  vtkNew<MessageObserver> observer;
  observer->Watch(reader);
  reader->SetFileName(good.c_str());
  reader->Update();
  EXPECT_GT(reader->GetOutput()->GetNumberOfSamples(), 0);
  reader->SetFileName(dir.File("image.png").c_str());
  reader->Update();
  EXPECT_NE(observer->Errors.find("not an OFB file"), std::string::npos);
  EXPECT_EQ(reader->GetOutput()->GetNumberOfSamples(), 0);
  EXPECT_EQ(reader->GetOutput()->GetNumberOfCells(), 0);
}

TEST(IO, ForgedCountsAreRejectedBeforeAllocating)
{
  TempDirectory dir;
  const std::string good = dir.File("good.ofb");
  const std::string bad = dir.File("bad.ofb");
  ASSERT_EQ(WriteOFB(SmallOFB(), good), "");
  const Bytes bytes = Load(good);
  const vtkTypeUInt64 cells = GetLE(bytes, 72, 8);
  const vtkTypeUInt64 samples = GetLE(bytes, 80, 8);
  const size_t h = vtkOFBWriter::HeaderSize - 4;
  struct Forgery
  {
    size_t At;
    int Size;
    vtkTypeUInt64 Value;
    std::string Expected;
  };
  const std::vector<Forgery> header = {
    { 80, 8, vtkTypeUInt64(1) << 60, "sample count" }, // 2^60 samples
    { 80, 8, 0xFFFFFFFEull, "bytes" },                 // 2^32 - 2 samples
    { 72, 8, vtkTypeUInt64(1) << 60, "cells" },        // 2^60 cells
    { 88, 4, 0xFFFFFFFFull, "arrays" },                // 2^32 - 1 arrays
    { 48, 8, vtkTypeUInt64(1) << 40, "dimensions" },   // a huge dimension
    { 56, 8, 0, "dimensions" },                        // a zero dimension
    { 40, 8, 0x7FF8000000000000ull, "frame" },         // a NaN cell size
    { 8, 4, 2, "version 2" },                          // a newer version
    { 12, 4, 0x04030201u, "byte-order" },              // big-endian marker
  };
  for (const Forgery& f : header)
  {
    SCOPED_TRACE("header field at " + std::to_string(f.At));
    Bytes forged = bytes;
    PutLE(forged, f.At, f.Value, f.Size);
    FixCRC(forged, 0, h);
    Save(bad, forged, forged.size());
    const double start = vtkTimerLog::GetUniversalTime();
    ExpectReadError(bad, f.Expected);
    EXPECT_LT(vtkTimerLog::GetUniversalTime() - start, 2.0);
  }

  // Sections with a valid checksum but invalid content.
  const size_t offsets = vtkOFBWriter::HeaderSize;
  const size_t depths = offsets + 4 * (cells + 1) + 4;
  const size_t arrays = FirstArrayOffset(bytes);
  {
    Bytes forged = bytes; // a decreasing offset
    PutLE(forged, offsets + 4 * (cells / 2), samples + 1, 4);
    FixCRC(forged, offsets, depths - 4);
    Save(bad, forged, forged.size());
    ExpectReadError(bad, "cell offsets");
  }
  {
    Bytes forged = bytes; // a NaN depth
    PutLE(forged, depths, 0x7FC00000u, 4);
    FixCRC(forged, depths, arrays - 4);
    Save(bad, forged, forged.size());
    ExpectReadError(bad, "depths");
  }
  const size_t name = static_cast<size_t>(GetLE(bytes, arrays, 4));
  const size_t fields = arrays + 4 + name;
  const std::vector<Forgery> array = {
    { fields, 4, 9999, "unknown data type" },             // unknown type
    { fields + 4, 4, 3, "unknown data type" },            // wrong element size
    { fields + 8, 4, 0x80000000u, "components" },         // 2^31 components
    { fields + 8, 4, 0, "components" },                   // no component
    { fields + 12, 8, samples + 1, "tuples" },            // tuples != samples
    { fields + 12, 8, vtkTypeUInt64(1) << 62, "tuples" }, // huge tuple count
    { fields + 20, 4, 1u << 20, "roles" },                // unknown role
    { fields + 20, 4, 1u << 2, "active" },                // colours as normals
    { arrays, 4, 0xFFFFFFF0u, "name length" },            // huge name
  };
  for (const Forgery& f : array)
  {
    SCOPED_TRACE("array field at " + std::to_string(f.At));
    Bytes forged = bytes;
    PutLE(forged, f.At, f.Value, f.Size);
    if (f.At != arrays)
    {
      FixCRC(forged, arrays, fields + 24);
    }
    Save(bad, forged, forged.size());
    ExpectReadError(bad, f.Expected);
  }
}

TEST(IO, ArraysMustFitTheirAttributeRoles)
{
  TempDirectory dir;
  const std::string good = dir.File("good.ofb");
  const std::string bad = dir.File("bad.ofb");
  ASSERT_EQ(WriteOFB(SmallOFB(), good), "");
  const Bytes bytes = Load(good);
  const std::vector<StoredArray> arrays = ListArrays(bytes);
  // Each role's array retyped to another type of the same size, its header CRC
  // recomputed: the values keep their bytes, only their meaning changes. Texture
  // coordinates as uint32 crashed vtkPLYWriter on export.
  struct Retyping
  {
    int Role;
    int Type;
  };
  const Retyping retypings[] = {
    { vtkDataSetAttributes::TCOORDS, VTK_UNSIGNED_INT },
    { vtkDataSetAttributes::TCOORDS, VTK_INT },
    { vtkDataSetAttributes::NORMALS, VTK_INT },
    { vtkDataSetAttributes::VECTORS, VTK_UNSIGNED_INT },
    { vtkDataSetAttributes::SCALARS, VTK_SIGNED_CHAR },
    { vtkDataSetAttributes::SCALARS, VTK_CHAR },
  };
  for (const Retyping& r : retypings)
  {
    SCOPED_TRACE(std::string(vtkDataSetAttributes::GetAttributeTypeAsString(r.Role)) + " as " +
      vtkImageScalarTypeNameMacro(r.Type));
    const StoredArray* a = ArrayWithRole(arrays, r.Role);
    ASSERT_TRUE(a);
    Bytes forged = bytes;
    Retype(forged, *a, r.Type);
    Save(bad, forged, forged.size());
    ExpectReadError(bad, "must hold");
    ExpectReadError(bad, a->Name);
  }

  // An array without a role may have any numeric type: the double "Pressure" read as
  // int64 loads.
  for (const StoredArray& a : arrays)
  {
    if (a.Name == "Pressure")
    {
      ASSERT_EQ(a.Roles, 0u);
      Bytes forged = bytes;
      Retype(forged, a, VTK_LONG_LONG);
      Save(bad, forged, forged.size());
      std::string errors;
      vtkSmartPointer<vtkOFB> back = ReadOFB(bad, errors);
      EXPECT_EQ(errors, "");
      ASSERT_TRUE(back->GetSampleData()->GetArray("Pressure"));
      EXPECT_EQ(back->GetSampleData()->GetArray("Pressure")->GetDataType(), VTK_LONG_LONG);
    }
  }
}

TEST(IO, WriterRefusesArraysThatDoNotFitTheirRoles)
{
  TempDirectory dir;
  const std::string path = dir.File("a.ofb");
  vtkSmartPointer<vtkOFB> ofb = SmallOFB();
  ASSERT_EQ(WriteOFB(ofb, path), "");
  const Bytes original = Load(path);
  const vtkIdType n = ofb->GetNumberOfSamples();
  vtkNew<vtkTypeUInt32Array> uv;
  uv->SetName("UV");
  uv->SetNumberOfComponents(2);
  uv->SetNumberOfTuples(n);
  uv->Fill(1);
  ofb->GetSampleData()->SetTCoords(uv);
  int result = 1;
  const std::string errors = WriteOFB(ofb, path, &result);
  EXPECT_NE(errors.find("texture coordinates"), std::string::npos) << errors;
  EXPECT_EQ(result, 0);
  EXPECT_EQ(Load(path), original);
}

TEST(IO, ImpossibleFramesAreRefused)
{
  TempDirectory dir;
  const std::string good = dir.File("good.ofb");
  const std::string bad = dir.File("bad.ofb");
  ASSERT_EQ(WriteOFB(SmallOFB(), good), "");
  const Bytes bytes = Load(good);
  const size_t h = vtkOFBWriter::HeaderSize - 4;
  auto bitsOf = [](double value)
  {
    vtkTypeUInt64 bits;
    std::memcpy(&bits, &value, sizeof(bits));
    return bits;
  };
  const double inf = std::numeric_limits<double>::infinity();
  struct Forgery
  {
    size_t At;
    int Size;
    vtkTypeUInt64 Value;
  };
  const Forgery header[] = {
    { 16, 8, bitsOf(1e308) },                  // origin x beyond float
    { 24, 8, bitsOf(-1e308) },                 // origin y beyond float
    { 32, 8, bitsOf(-inf) },                   // infinite origin z
    { 40, 8, bitsOf(0.0) },                    // no cell size
    { 40, 8, bitsOf(-0.1) },                   // a negative cell size
    { 40, 8, bitsOf(inf) },                    // an infinite cell size
    { 40, 8, bitsOf(1e38) },                   // a box beyond float
    { 40, 8, bitsOf(4.9e-324) },               // a cell size whose inverse overflows
    { 48, 8, 0xFFFFFFFFull },                  // 2^32 - 1 cells along x
    { 48, 8, 0x80000000ull },                  // products over 2^32 cells
    { 48, 8, static_cast<vtkTypeUInt64>(-1) }, // a negative dimension
  };
  for (const Forgery& f : header)
  {
    SCOPED_TRACE("header field at " + std::to_string(f.At) + " = " + std::to_string(f.Value));
    Bytes forged = bytes;
    PutLE(forged, f.At, f.Value, f.Size);
    FixCRC(forged, 0, h);
    Save(bad, forged, forged.size());
    ExpectReadError(bad, "the header announces");
  }
  // A box that starts within float and ends beyond it.
  {
    Bytes forged = bytes;
    PutLE(forged, 16, bitsOf(3e38), 8);
    PutLE(forged, 40, bitsOf(1e37), 8);
    FixCRC(forged, 0, h);
    Save(bad, forged, forged.size());
    ExpectReadError(bad, "beyond the range of float");
  }
  // Two dimensions of 2^32 - 1: their product fits in 64 bits, not in an OFB's cell indices.
  {
    Bytes forged = bytes;
    PutLE(forged, 48, 0xFFFFFFFFull, 8);
    PutLE(forged, 56, 0xFFFFFFFFull, 8);
    FixCRC(forged, 0, h);
    Save(bad, forged, forged.size());
    ExpectReadError(bad, "dimensions");
  }

  // Depths outside the box (still finite and sorted within their cell), CRC recomputed:
  // the last sample (the deepest of its cell) far beyond, the first far before.
  const vtkTypeUInt64 cells = GetLE(bytes, 72, 8);
  const vtkTypeUInt64 samples = GetLE(bytes, 80, 8);
  const size_t depths = vtkOFBWriter::HeaderSize + 4 * (cells + 1) + 4;
  const size_t arrays = FirstArrayOffset(bytes);
  const std::pair<vtkTypeUInt64, float> outside[] = {
    { samples - 1, 3e38f },
    { 0, -3e38f },
    { samples - 1, 1000.0f },
    { 0, -1e-3f },
  };
  for (const auto& o : outside)
  {
    SCOPED_TRACE("depth " + std::to_string(o.first) + " = " + std::to_string(o.second));
    Bytes forged = bytes;
    vtkTypeUInt32 bits;
    std::memcpy(&bits, &o.second, sizeof(bits));
    PutLE(forged, depths + 4 * o.first, bits, 4);
    FixCRC(forged, depths, arrays - 4);
    Save(bad, forged, forged.size());
    ExpectReadError(bad, "outside the box");
  }
}

TEST(IO, ArrayNamesWithANulByteAreRejected)
{
  TempDirectory dir;
  const std::string good = dir.File("good.ofb");
  const std::string bad = dir.File("bad.ofb");
  ASSERT_EQ(WriteOFB(SmallOFB(), good), "");
  const Bytes bytes = Load(good);
  const size_t arrays = FirstArrayOffset(bytes);
  const size_t length = static_cast<size_t>(GetLE(bytes, arrays, 4));
  ASSERT_GE(length, 3u);
  // "Co\0ors" would come back as "Co": a NUL anywhere in the name, CRC fixed.
  for (const size_t at : { size_t(0), size_t(2), length - 1 })
  {
    Bytes forged = bytes;
    forged[arrays + 4 + at] = 0;
    FixCRC(forged, arrays, arrays + 4 + length + 24);
    Save(bad, forged, forged.size());
    ExpectReadError(bad, "NUL");
  }
}

TEST(IO, WriterErrorsAndAtomicReplace)
{
  TempDirectory dir;
  const std::string path = dir.File("a.ofb");
  vtkSmartPointer<vtkOFB> first = SmallOFB();
  int result = 0;
  ASSERT_EQ(WriteOFB(first, path, &result), "");
  EXPECT_EQ(result, 1);
  const Bytes original = Load(path);

  // No file name; a directory that does not exist.
  std::string errors = WriteOFB(first, "", &result);
  EXPECT_NE(errors.find("FileName"), std::string::npos) << errors;
  EXPECT_EQ(result, 0);
  errors = WriteOFB(first, dir.File("missing/a.ofb"), &result);
  EXPECT_NE(errors.find("missing/a.ofb"), std::string::npos) << errors;
  EXPECT_EQ(result, 0);
  EXPECT_FALSE(vtksys::SystemTools::FileExists(dir.File("missing")));

  // An inconsistent OFB is refused and the old file is left intact.
  vtkNew<vtkOFB> broken;
  broken->DeepCopy(first);
  vtkNew<vtkFloatArray> wrong;
  wrong->SetName("Wrong");
  wrong->SetNumberOfTuples(3);
  broken->GetSampleData()->AddArray(wrong);
  errors = WriteOFB(broken, path, &result);
  EXPECT_NE(errors.find("Wrong"), std::string::npos) << errors;
  EXPECT_EQ(result, 0);
  EXPECT_EQ(Load(path), original);

  // So is an OFB that the reader would reject (a NaN depth).
  vtkNew<vtkOFB> nan;
  nan->DeepCopy(first);
  nan->GetDepths()->SetValue(0, std::numeric_limits<float>::quiet_NaN());
  errors = WriteOFB(nan, path, &result);
  EXPECT_NE(errors.find("inconsistent"), std::string::npos) << errors;
  EXPECT_EQ(result, 0);
  EXPECT_EQ(Load(path), original);

  // A directory is refused before anything is written.
  vtksys::SystemTools::MakeDirectory(dir.File("adir"));
  errors = WriteOFB(first, dir.File("adir"), &result);
  EXPECT_NE(errors.find("is a directory, not a regular file"), std::string::npos) << errors;
  EXPECT_EQ(result, 0);
  EXPECT_TRUE(vtksys::SystemTools::FileIsDirectory(dir.File("adir")));

  // A successful second write replaces the content, and leaves no temporary file.
  vtkSmartPointer<vtkPolyData> sphere = MakeSphere(1.0, 16);
  vtkSmartPointer<vtkOFB> second = Build(sphere, 40);
  ASSERT_NE(second->GetNumberOfSamples(), first->GetNumberOfSamples());
  ASSERT_EQ(WriteOFB(second, path, &result), "");
  EXPECT_EQ(result, 1);
  std::vector<std::string> names = dir.List();
  std::sort(names.begin(), names.end());
  EXPECT_EQ(names, (std::vector<std::string>{ "a.ofb", "adir" }));
  std::string readErrors;
  vtkSmartPointer<vtkOFB> back = ReadOFB(path, readErrors);
  EXPECT_EQ(readErrors, "");
  ExpectSameOFB(second, back);
}

TEST(IO, PrintSelf)
{
  vtkNew<vtkOFBWriter> writer;
  writer->SetFileName("out.ofb");
  std::ostringstream w;
  writer->Print(w);
  EXPECT_NE(w.str().find("FileName: out.ofb"), std::string::npos);
  EXPECT_NE(w.str().find("FormatVersion: 1"), std::string::npos);
  vtkNew<vtkOFBReader> reader;
  std::ostringstream r;
  reader->Print(r);
  EXPECT_NE(r.str().find("FileName: (none)"), std::string::npos);
}
