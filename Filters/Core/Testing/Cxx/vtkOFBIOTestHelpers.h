// Helpers of the file I/O tests (TestOFBIO.cxx, TestOFBWriterSafety.cxx): a scratch
// directory, raw file bytes, writing and reading with the errors caught, exact comparison.
#ifndef vtkOFBIOTestHelpers_h
#define vtkOFBIOTestHelpers_h

#include "vtkOFBTempDirectory.h"
#include "vtkOFBTestUtilities.h"

#include "vtkDoubleArray.h"
#include "vtkFloatArray.h"
#include "vtkIntArray.h"
#include "vtkOFBReader.h"
#include "vtkOFBWriter.h"
#include "vtkPointData.h"
#include "vtkTypeUInt32Array.h"

#include <vtksys/SystemTools.hxx>

#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <fstream>
#include <iterator>
#include <string>
#include <vector>

namespace vtkofbtest
{
using Bytes = std::vector<unsigned char>;

inline Bytes Load(const std::string& path)
{
  std::ifstream in(path, std::ios::binary);
  return Bytes(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
}

inline void Save(const std::string& path, const Bytes& bytes, size_t size)
{
  std::ofstream out(path, std::ios::binary | std::ios::trunc);
  out.write(reinterpret_cast<const char*>(bytes.data()), static_cast<std::streamsize>(size));
}

inline vtkTypeUInt64 GetLE(const Bytes& b, size_t at, int size)
{
  vtkTypeUInt64 v = 0;
  for (int i = size - 1; i >= 0; --i)
  {
    v = (v << 8) | b[at + i];
  }
  return v;
}

inline void PutLE(Bytes& b, size_t at, vtkTypeUInt64 v, int size)
{
  for (int i = 0; i < size; ++i)
  {
    b[at + i] = static_cast<unsigned char>(v >> (8 * i));
  }
}

/// Recompute the CRC-32 of the section [begin, end), stored at `end`.
inline void FixCRC(Bytes& b, size_t begin, size_t end)
{
  PutLE(b, end, vtkOFBWriter::UpdateCRC32(0, b.data() + begin, end - begin), 4);
}

/// Counts the progress events of an algorithm and keeps the last value.
class ProgressCounter : public vtkCommand
{
public:
  static ProgressCounter* New() { return new ProgressCounter; }
  void Execute(vtkObject*, unsigned long, void* data) override
  {
    ++this->Count;
    this->Last = *static_cast<double*>(data);
  }
  int Count = 0;
  double Last = -1.0;
};

/// Write `ofb` to `path`; returns the errors, Write()'s result in `result`.
inline std::string WriteOFB(vtkOFB* ofb,
  const std::string& path,
  int* result = nullptr,
  ProgressCounter* progress = nullptr)
{
  vtkNew<vtkOFBWriter> writer;
  vtkNew<MessageObserver> observer;
  observer->Watch(writer);
  if (progress)
  {
    writer->AddObserver(vtkCommand::ProgressEvent, progress);
  }
  writer->SetInputData(ofb);
  writer->SetFileName(path.empty() ? nullptr : path.c_str());
  const int ok = writer->Write();
  if (result)
  {
    *result = ok;
  }
  return observer->Errors;
}

/// Read `path`; returns the output OFB and the errors in `errors`.
inline vtkSmartPointer<vtkOFB> ReadOFB(const std::string& path,
  std::string& errors,
  ProgressCounter* progress = nullptr)
{
  vtkNew<vtkOFBReader> reader;
  vtkNew<MessageObserver> observer;
  observer->Watch(reader);
  if (progress)
  {
    reader->AddObserver(vtkCommand::ProgressEvent, progress);
  }
  reader->SetFileName(path.c_str());
  reader->Update();
  errors = observer->Errors;
  vtkSmartPointer<vtkOFB> out = reader->GetOutput();
  return out;
}

/// Reading `path` must fail with an error that contains `expected` and give an empty OFB.
inline void ExpectReadError(const std::string& path, const std::string& expected = "")
{
  std::string errors;
  vtkSmartPointer<vtkOFB> ofb = ReadOFB(path, errors);
  EXPECT_FALSE(errors.empty());
  EXPECT_NE(errors.find(expected), std::string::npos) << errors;
  EXPECT_EQ(ofb->GetNumberOfSamples(), 0);
  EXPECT_EQ(ofb->GetNumberOfCells(), 0);
  EXPECT_EQ(ofb->GetCellSize(), 0.0);
  EXPECT_EQ(ofb->GetSampleData()->GetNumberOfArrays(), 0);
}

template<typename T>
inline bool SameBits(const T* a, const T* b, vtkIdType n)
{
  return n == 0 || std::memcmp(a, b, sizeof(T) * static_cast<size_t>(n)) == 0;
}

/// `b` must be an exact copy of `a`: frame, offsets, depths, cell index, arrays, roles.
inline void ExpectSameOFB(vtkOFB* a, vtkOFB* b)
{
  EXPECT_EQ(std::memcmp(a->GetOrigin(), b->GetOrigin(), 3 * sizeof(double)), 0);
  EXPECT_EQ(a->GetCellSize(), b->GetCellSize());
  for (int k = 0; k < 3; ++k)
  {
    EXPECT_EQ(a->GetDimensions()[k], b->GetDimensions()[k]);
  }
  ASSERT_EQ(a->GetNumberOfCells(), b->GetNumberOfCells());
  ASSERT_EQ(a->GetNumberOfSamples(), b->GetNumberOfSamples());
  const vtkIdType n = a->GetNumberOfSamples();
  EXPECT_TRUE(SameBits(a->GetCellOffsets()->GetPointer(0),
    b->GetCellOffsets()->GetPointer(0),
    a->GetNumberOfCells() + 1));
  EXPECT_TRUE(SameBits(a->GetDepths()->GetPointer(0), b->GetDepths()->GetPointer(0), n));
  ASSERT_EQ(b->GetCellIndex()->GetNumberOfValues(), n);
  EXPECT_TRUE(SameBits(a->GetCellIndex()->GetPointer(0), b->GetCellIndex()->GetPointer(0), n));
  vtkPointData* sa = a->GetSampleData();
  vtkPointData* sb = b->GetSampleData();
  ASSERT_EQ(sa->GetNumberOfArrays(), sb->GetNumberOfArrays());
  for (int i = 0; i < sa->GetNumberOfArrays(); ++i)
  {
    vtkDataArray* x = sa->GetArray(i);
    vtkDataArray* y = sb->GetArray(i);
    ASSERT_TRUE(x && y);
    const std::string name = x->GetName() ? x->GetName() : "";
    EXPECT_EQ(name, y->GetName() ? y->GetName() : "");
    EXPECT_EQ(x->GetDataType(), y->GetDataType()) << name;
    ASSERT_EQ(x->GetNumberOfComponents(), y->GetNumberOfComponents()) << name;
    ASSERT_EQ(x->GetNumberOfTuples(), y->GetNumberOfTuples()) << name;
    const vtkIdType values = x->GetNumberOfValues();
    if (x->HasStandardMemoryLayout())
    {
      EXPECT_TRUE(values == 0 ||
        std::memcmp(x->GetVoidPointer(0),
          y->GetVoidPointer(0),
          static_cast<size_t>(values) * x->GetDataTypeSize()) == 0)
        << name;
    }
    else
    {
      for (vtkIdType v = 0; v < values; ++v)
      {
        const int c = x->GetNumberOfComponents();
        ASSERT_EQ(x->GetComponent(v / c, v % c), y->GetComponent(v / c, v % c)) << name;
      }
    }
    for (int k = 0; k < vtkDataSetAttributes::NUM_ATTRIBUTES; ++k)
    {
      EXPECT_EQ(sa->GetAbstractAttribute(k) == x, sb->GetAbstractAttribute(k) == y)
        << name << " role " << k;
    }
  }
}

/// Add a double array "Pressure", a two-component int array "Label", a float vector
/// field "Flow" and float texture coordinates to the points of `mesh`.
inline void AddPointArrays(vtkPolyData* mesh)
{
  const vtkIdType n = mesh->GetNumberOfPoints();
  vtkNew<vtkDoubleArray> pressure;
  pressure->SetName("Pressure");
  vtkNew<vtkIntArray> label;
  label->SetName("Label");
  label->SetNumberOfComponents(2);
  vtkNew<vtkFloatArray> flow;
  flow->SetName("Flow");
  flow->SetNumberOfComponents(3);
  vtkNew<vtkFloatArray> uv;
  uv->SetName("UV");
  uv->SetNumberOfComponents(2);
  for (vtkIdType i = 0; i < n; ++i)
  {
    double p[3];
    mesh->GetPoint(i, p);
    pressure->InsertNextValue(std::sin(37.0 * p[0]) + p[1] * p[2] / 3.0);
    const int l[2] = { static_cast<int>(i % 13), -static_cast<int>(i % 1000003) };
    label->InsertNextTypedTuple(l);
    const float f[3] = { static_cast<float>(-p[1]), static_cast<float>(p[0]), 0.25f };
    flow->InsertNextTypedTuple(f);
    const float t[2] = { static_cast<float>(p[0] + 0.5), static_cast<float>(p[2] * 2.0) };
    uv->InsertNextTypedTuple(t);
  }
  mesh->GetPointData()->AddArray(pressure);
  mesh->GetPointData()->AddArray(label);
  mesh->GetPointData()->SetVectors(flow);
  mesh->GetPointData()->SetTCoords(uv);
}

/// A small OFB (a sphere at a low resolution) with arrays of several types.
inline vtkSmartPointer<vtkOFB> SmallOFB()
{
  vtkSmartPointer<vtkPolyData> sphere = MakeSphere(1.0, 16);
  AddPointArrays(sphere);
  return Build(sphere, 24);
}

/// Offset of the first sample array in a file of `b`.
inline size_t FirstArrayOffset(const Bytes& b)
{
  const vtkTypeUInt64 cells = GetLE(b, 72, 8);
  const vtkTypeUInt64 samples = GetLE(b, 80, 8);
  return static_cast<size_t>(vtkOFBWriter::HeaderSize + 4 * (cells + 1) + 4 + 4 * samples + 4);
}

/// Where a sample array lies in the bytes of a file (see vtkOFBWriter's layout).
struct StoredArray
{
  std::string Name;
  size_t Start = 0;  // the name length, which starts the array header
  size_t Fields = 0; // type, element size, components, tuples, roles (24 bytes)
  size_t Values = 0; // the values, after the CRC of the array header
  size_t Size = 0;   // bytes of values, before their CRC
  vtkTypeUInt32 Roles = 0;
};

/// The sample arrays of the valid file `b`.
inline std::vector<StoredArray> ListArrays(const Bytes& b)
{
  std::vector<StoredArray> arrays;
  const vtkTypeUInt64 count = GetLE(b, 88, 4);
  const vtkTypeUInt64 samples = GetLE(b, 80, 8);
  size_t at = FirstArrayOffset(b);
  for (vtkTypeUInt64 k = 0; k < count; ++k)
  {
    StoredArray a;
    a.Start = at;
    const size_t length = static_cast<size_t>(GetLE(b, at, 4));
    a.Name.assign(reinterpret_cast<const char*>(b.data()) + at + 4, length);
    a.Fields = at + 4 + length;
    a.Roles = static_cast<vtkTypeUInt32>(GetLE(b, a.Fields + 20, 4));
    a.Values = a.Fields + 24 + 4;
    a.Size = static_cast<size_t>(samples * GetLE(b, a.Fields + 8, 4) * GetLE(b, a.Fields + 4, 4));
    at = a.Values + a.Size + 4;
    arrays.push_back(a);
  }
  return arrays;
}

/// The stored array that plays attribute role `role`, or nullptr.
inline const StoredArray* ArrayWithRole(const std::vector<StoredArray>& arrays, int role)
{
  for (const StoredArray& a : arrays)
  {
    if ((a.Roles >> role) & 1u)
    {
      return &a;
    }
  }
  return nullptr;
}

/// Give stored array `a` the VTK type `type` (of the same element size) and reseal its header.
inline void Retype(Bytes& b, const StoredArray& a, int type)
{
  PutLE(b, a.Fields, static_cast<vtkTypeUInt64>(type), 4);
  FixCRC(b, a.Start, a.Fields + 24);
}
}

#endif
