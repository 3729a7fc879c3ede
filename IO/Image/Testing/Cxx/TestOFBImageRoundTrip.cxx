// vtkOFBImageWriter then vtkOFBImageReader: every lossless format and sample type bit for
// bit (PNG 8 and 16 bits, TIFF, BMP, PNM, OpenEXR float and half), the lossy ones within
// their precision (JPEG, Radiance HDR), the orientation against VTK's own PNG reader and
// writer, and the replacement of an existing file.
#include "vtkOFBImageTestHelpers.h"

#include "vtkFloatArray.h"
#include "vtkPNGReader.h"
#include "vtkPNGWriter.h"
#include "vtkUnsignedCharArray.h"
#include "vtkUnsignedShortArray.h"

#include <cmath>
#include <cstring>
#include <limits>

using namespace vtkofbtest;

namespace
{
/// A test pattern of `type`: each component's values differ between neighbours, rows and
/// components, and use the type's whole range (16-bit values no byte holds).
double Pattern(int type, int i, int j, int c)
{
  const int k = (i * 7 + j * 13 + c * 29) % 64;
  switch (type)
  {
    case VTK_UNSIGNED_CHAR:
      return (k * 4 + c) % 256;
    case VTK_UNSIGNED_SHORT:
      return (k * 1021 + 257 * c + 1) % 65536;
    case VTK_FLOAT:
      return (k - 20) * 0.123456789 + c * 1e-7 + (j == 0 ? 1e-39 : 0.0); // a subnormal too
    default: // positive floats (for Radiance HDR)
      return 0.5 + k * 0.123456789 + c * 0.01;
  }
}

/// The image round-tripped through `name`, checked equal to the original (exactly, or
/// within `tolerance` of the type's range).
void RoundTrip(const ImageDirectory& dir,
  const std::string& name,
  int type,
  int nc,
  double tolerance = 0.0,
  const char* format = nullptr)
{
  SCOPED_TRACE(name + " " + std::to_string(nc) + " components");
  const int pattern = type == VTK_FLOAT && tolerance > 0.0 ? VTK_VOID : type;
  vtkSmartPointer<vtkImageData> image = MakeImage(
    13, 7, type, nc, [pattern](int i, int j, int c) { return Pattern(pattern, i, j, c); });
  vtkNew<MessageObserver> o;
  ASSERT_TRUE(WriteImage(image, dir.File(name), o)) << o->Errors;
  vtkNew<vtkOFBImageReader> reader;
  vtkSmartPointer<vtkImageData> back = ReadImage(dir.File(name), o, reader);
  ASSERT_TRUE(o->Errors.empty()) << o->Errors;
  if (format)
  {
    EXPECT_STREQ(reader->GetFormatName(), format);
  }
  int dims[3];
  back->GetDimensions(dims);
  ASSERT_EQ(dims[0], 13);
  ASSERT_EQ(dims[1], 7);
  ASSERT_EQ(dims[2], 1);
  vtkDataArray* a = image->GetPointData()->GetScalars();
  vtkDataArray* b = back->GetPointData()->GetScalars();
  ASSERT_NE(b, nullptr);
  EXPECT_EQ(b->GetDataType(), type);
  ASSERT_EQ(b->GetNumberOfComponents(), nc);
  ASSERT_EQ(b->GetNumberOfTuples(), a->GetNumberOfTuples());
  if (tolerance == 0.0)
  {
    // Bit for bit.
    EXPECT_EQ(
      std::memcmp(
        a->GetVoidPointer(0), b->GetVoidPointer(0), a->GetNumberOfValues() * a->GetDataTypeSize()),
      0);
    return;
  }
  // Relative to the largest component of the pixel (and at least 1).
  double worst = 0.0;
  for (vtkIdType t = 0; t < a->GetNumberOfTuples(); ++t)
  {
    double largest = 1.0;
    for (int c = 0; c < nc; ++c)
    {
      largest = std::max(largest, std::abs(a->GetComponent(t, c)));
    }
    for (int c = 0; c < nc; ++c)
    {
      worst = std::max(worst, std::abs(a->GetComponent(t, c) - b->GetComponent(t, c)) / largest);
    }
  }
  EXPECT_LE(worst, tolerance);
}
}

//------------------------------------------------------------------------------
TEST(ImageRoundTrip, LosslessFormatsBitForBit)
{
  ImageDirectory dir;
  for (int nc = 1; nc <= 4; ++nc)
  {
    RoundTrip(dir, "u8-" + std::to_string(nc) + ".png", VTK_UNSIGNED_CHAR, nc, 0.0, "png");
    RoundTrip(dir, "u16-" + std::to_string(nc) + ".png", VTK_UNSIGNED_SHORT, nc, 0.0, "png");
    RoundTrip(dir, "u8-" + std::to_string(nc) + ".tif", VTK_UNSIGNED_CHAR, nc, 0.0, "tiff");
    RoundTrip(dir, "u16-" + std::to_string(nc) + ".tif", VTK_UNSIGNED_SHORT, nc, 0.0, "tiff");
    RoundTrip(dir, "f32-" + std::to_string(nc) + ".tif", VTK_FLOAT, nc, 0.0, "tiff");
    RoundTrip(dir, "f32-" + std::to_string(nc) + ".exr", VTK_FLOAT, nc, 0.0, "openexr");
  }
  RoundTrip(dir, "u8.bmp", VTK_UNSIGNED_CHAR, 3, 0.0, "bmp");
  RoundTrip(dir, "u8.ppm", VTK_UNSIGNED_CHAR, 3, 0.0, "pnm");
  RoundTrip(dir, "u8.pgm", VTK_UNSIGNED_CHAR, 1, 0.0, "pnm");
}

//------------------------------------------------------------------------------
TEST(ImageRoundTrip, LossyFormatsWithinTheirPrecision)
{
  ImageDirectory dir;
  // Radiance HDR: positive RGB with an 8-bit mantissa under a shared exponent (within
  // 1% of the largest component of a pixel).
  RoundTrip(dir, "rgb.hdr", VTK_FLOAT, 3, 0.01, "hdr");
  // JPEG at quality 95, on a smooth picture.
  vtkSmartPointer<vtkImageData> smooth = MakeImage(64,
    48,
    VTK_UNSIGNED_CHAR,
    3,
    [](int i, int j, int c) { return 40.0 + 2.0 * i + j + 30.0 * c; });
  vtkNew<MessageObserver> o;
  ASSERT_TRUE(WriteImage(smooth, dir.File("smooth.jpg"), o)) << o->Errors;
  vtkNew<vtkOFBImageReader> reader;
  vtkSmartPointer<vtkImageData> back = ReadImage(dir.File("smooth.jpg"), o, reader);
  ASSERT_TRUE(o->Errors.empty()) << o->Errors;
  EXPECT_STREQ(reader->GetFormatName(), "jpeg");
  vtkDataArray* a = smooth->GetPointData()->GetScalars();
  vtkDataArray* b = back->GetPointData()->GetScalars();
  ASSERT_EQ(b->GetNumberOfTuples(), a->GetNumberOfTuples());
  ASSERT_EQ(b->GetDataType(), VTK_UNSIGNED_CHAR);
  double sum = 0.0;
  for (vtkIdType v = 0; v < a->GetNumberOfValues(); ++v)
  {
    sum += std::abs(a->GetComponent(v / 3, v % 3) - b->GetComponent(v / 3, v % 3));
  }
  EXPECT_LT(sum / a->GetNumberOfValues(), 2.0);
  // Half-float OpenEXR: values that half holds exactly come back exactly.
  vtkSmartPointer<vtkImageData> halves = MakeImage(
    9, 5, VTK_FLOAT, 4, [](int i, int j, int c) { return (i - 4) * 0.25 + j * 16.0 + c / 8.0; });
  ASSERT_TRUE(WriteImage(halves, dir.File("half.exr"), o, true)) << o->Errors;
  back = ReadImage(dir.File("half.exr"), o, reader);
  EXPECT_EQ(reader->GetFileBitsPerSample(), 16);
  a = halves->GetPointData()->GetScalars();
  b = back->GetPointData()->GetScalars();
  ASSERT_EQ(b->GetDataType(), VTK_FLOAT);
  ASSERT_EQ(b->GetNumberOfValues(), a->GetNumberOfValues());
  EXPECT_EQ(std::memcmp(a->GetVoidPointer(0), b->GetVoidPointer(0), 4 * a->GetNumberOfValues()), 0);
  // And 32-bit float is the default: a value half cannot hold stays.
  ASSERT_TRUE(WriteImage(
    MakeImage(2, 2, VTK_FLOAT, 1, [](int, int, int) { return 0.1; }), dir.File("full.exr"), o))
    << o->Errors;
  back = ReadImage(dir.File("full.exr"), o, reader);
  EXPECT_EQ(reader->GetFileBitsPerSample(), 32);
  EXPECT_EQ(static_cast<float>(back->GetPointData()->GetScalars()->GetComponent(0, 0)), 0.1f);
}

//------------------------------------------------------------------------------
TEST(ImageRoundTrip, RowZeroIsTheBottomAsInVTK)
{
  // Each way against VTK's PNG reader and writer, which put row 0 at the bottom: a
  // double flip would pass a round trip through vtkOFBImageWriter/Reader alone.
  ImageDirectory dir;
  vtkSmartPointer<vtkImageData> image = MakeImage(
    5, 4, VTK_UNSIGNED_CHAR, 3, [](int i, int j, int c) { return 10 * j + i + 100 * (c == 1); });
  vtkNew<vtkPNGWriter> vtkWriter;
  vtkWriter->SetInputData(image);
  vtkWriter->SetFileName(dir.File("vtk.png").c_str());
  vtkWriter->Write();
  vtkSmartPointer<vtkImageData> read = ReadImage(dir.File("vtk.png"));
  vtkDataArray* a = image->GetPointData()->GetScalars();
  vtkDataArray* b = read->GetPointData()->GetScalars();
  ASSERT_NE(b, nullptr);
  ASSERT_EQ(b->GetNumberOfValues(), a->GetNumberOfValues());
  for (vtkIdType v = 0; v < a->GetNumberOfValues(); ++v)
  {
    ASSERT_EQ(a->GetComponent(v / 3, v % 3), b->GetComponent(v / 3, v % 3)) << v;
  }
  ASSERT_TRUE(WriteImage(image, dir.File("ofb.png")));
  vtkNew<vtkPNGReader> vtkReader;
  vtkReader->SetFileName(dir.File("ofb.png").c_str());
  vtkReader->Update();
  b = vtkReader->GetOutput()->GetPointData()->GetScalars();
  ASSERT_EQ(b->GetNumberOfValues(), a->GetNumberOfValues());
  for (vtkIdType v = 0; v < a->GetNumberOfValues(); ++v)
  {
    ASSERT_EQ(a->GetComponent(v / 3, v % 3), b->GetComponent(v / 3, v % 3)) << v;
  }
}

//------------------------------------------------------------------------------
TEST(ImageRoundTrip, ReplacesAnExistingFileAndLeavesNoTemporary)
{
  ImageDirectory dir;
  const std::string path = dir.File("t.png");
  ASSERT_TRUE(
    WriteImage(MakeImage(4, 4, VTK_UNSIGNED_CHAR, 1, [](int, int, int) { return 7; }), path));
  ASSERT_TRUE(
    WriteImage(MakeImage(3, 2, VTK_UNSIGNED_CHAR, 1, [](int, int, int) { return 9; }), path));
  vtkSmartPointer<vtkImageData> back = ReadImage(path);
  EXPECT_EQ(back->GetDimensions()[0], 3);
  EXPECT_EQ(back->GetPointData()->GetScalars()->GetComponent(0, 0), 9.0);
  // A failed write (a type no format is given) keeps the old file.
  vtkNew<MessageObserver> o;
  EXPECT_FALSE(
    WriteImage(MakeImage(2, 2, VTK_DOUBLE, 1, [](int, int, int) { return 1; }), path, o));
  EXPECT_NE(o->Errors.find("double"), std::string::npos) << o->Errors;
  EXPECT_EQ(ReadImage(path)->GetDimensions()[0], 3);
  vtksys::Directory listing;
  listing.Load(dir.Path);
  EXPECT_EQ(listing.GetNumberOfFiles(), 3u); // ".", ".." and t.png
}
