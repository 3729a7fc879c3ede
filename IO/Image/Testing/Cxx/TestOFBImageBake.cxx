// Images between files and OFBs: float sample arrays baked by vtkOFBTextureBaker into
// 32-bit float OpenEXR textures that read back bit for bit; a 16-bit TIFF and a float
// OpenEXR stamped as decals (vtkOFBDecalPatch and vtkOFBTextureProjector) with the
// colours their 16 bits or floats give, not those of their top bytes.
#include "vtkOFBImageTestHelpers.h"

#include "vtkDoubleArray.h"
#include "vtkFloatArray.h"
#include "vtkOFB.h"
#include "vtkOFBDecalPatch.h"
#include "vtkOFBTextureBaker.h"
#include "vtkOFBTextureProjector.h"
#include "vtkUnsignedCharArray.h"
#include "vtkUnsignedShortArray.h"

#include <cmath>
#include <cstring>
#include <set>

using namespace vtkofbtest;

namespace
{
/// Add a float array `name` with values that need all of float's bits (and are not
/// multiples of 1/255): sin(37 x) * 1000 + y / 3 at each sample.
void AddFineArray(vtkOFB* ofb, const char* name)
{
  AddSampleArray(
    ofb, name, [](const double x[3]) { return std::sin(37.0 * x[0]) * 1000.0 + x[1] / 3.0; });
}
}

//------------------------------------------------------------------------------
TEST(ImageBake, FloatBakeReadsBackFromOpenEXRBitForBit)
{
  vtkSmartPointer<vtkPolyData> plane = MakeTexturedPlane(8);
  vtkSmartPointer<vtkOFB> ofb = Build(plane, 96);
  AddFineArray(ofb, "LIC");
  vtkNew<vtkOFBTextureBaker> baker;
  baker->SetInputData(plane);
  baker->SetOFBData(ofb);
  baker->SetArrayName("LIC");
  baker->SetTextureSize(128, 96);
  baker->Update();
  vtkImageData* baked = baker->GetOutput();
  auto* texels = vtkFloatArray::SafeDownCast(baked->GetPointData()->GetScalars());
  ASSERT_NE(texels, nullptr);
  EXPECT_GT(baker->GetNumberOfBakedTexels(), 128 * 96 * 9 / 10);
  // Far more distinct values than 8 or 16 bits hold.
  std::set<float> distinct(
    texels->GetPointer(0), texels->GetPointer(0) + texels->GetNumberOfValues());
  EXPECT_GT(distinct.size(), 65536u / 8);

  ImageDirectory dir;
  vtkNew<MessageObserver> o;
  ASSERT_TRUE(WriteImage(baked, dir.File("lic.exr"), o)) << o->Errors;
  vtkNew<vtkOFBImageReader> reader;
  vtkSmartPointer<vtkImageData> back = ReadImage(dir.File("lic.exr"), o, reader);
  ASSERT_TRUE(o->Errors.empty()) << o->Errors;
  EXPECT_STREQ(reader->GetFormatName(), "openexr");
  EXPECT_EQ(reader->GetFileBitsPerSample(), 32);
  auto* read = vtkFloatArray::SafeDownCast(back->GetPointData()->GetScalars());
  ASSERT_NE(read, nullptr);
  ASSERT_EQ(read->GetNumberOfComponents(), 1);
  ASSERT_EQ(read->GetNumberOfTuples(), texels->GetNumberOfTuples());
  EXPECT_EQ(back->GetDimensions()[0], 128);
  EXPECT_EQ(back->GetDimensions()[1], 96);
  EXPECT_EQ(
    std::memcmp(read->GetPointer(0), texels->GetPointer(0), 4 * read->GetNumberOfValues()), 0);
}

//------------------------------------------------------------------------------
TEST(ImageBake, DoubleArrayBakesToFloatOnRequest)
{
  vtkSmartPointer<vtkPolyData> plane = MakeTexturedPlane(8);
  vtkSmartPointer<vtkOFB> ofb = Build(plane, 64);
  vtkNew<vtkDoubleArray> field;
  field->SetName("Pressure");
  field->SetNumberOfValues(ofb->GetNumberOfSamples());
  for (vtkIdType i = 0; i < ofb->GetNumberOfSamples(); ++i)
  {
    double x[3];
    ofb->GetSamplePosition(i, x);
    field->SetValue(i, 101325.0 + 1234.5678 * x[0] * x[1]);
  }
  ofb->GetSampleData()->AddArray(field);
  vtkNew<vtkOFBTextureBaker> same, asFloat;
  for (vtkOFBTextureBaker* baker : { same.Get(), asFloat.Get() })
  {
    baker->SetInputData(plane);
    baker->SetOFBData(ofb);
    baker->SetArrayName("Pressure");
    baker->SetTextureSize(32, 32);
  }
  asFloat->SetOutputScalarTypeToFloat();
  same->Update();
  asFloat->Update();
  vtkDataArray* doubles = same->GetOutput()->GetPointData()->GetScalars();
  auto* floats = vtkFloatArray::SafeDownCast(asFloat->GetOutput()->GetPointData()->GetScalars());
  ASSERT_EQ(doubles->GetDataType(), VTK_DOUBLE);
  ASSERT_NE(floats, nullptr);
  EXPECT_STREQ(floats->GetName(), "Pressure");
  ASSERT_EQ(floats->GetNumberOfTuples(), doubles->GetNumberOfTuples());
  for (vtkIdType t = 0; t < floats->GetNumberOfTuples(); ++t)
  {
    ASSERT_EQ(floats->GetValue(t), static_cast<float>(doubles->GetComponent(t, 0))) << t;
  }
  // The double bake itself is refused by the writer with the cure named; the float one
  // is written.
  ImageDirectory dir;
  vtkNew<MessageObserver> o;
  EXPECT_FALSE(WriteImage(same->GetOutput(), dir.File("p.exr"), o));
  EXPECT_NE(o->Errors.find("convert them first"), std::string::npos) << o->Errors;
  o->Clear();
  EXPECT_TRUE(WriteImage(asFloat->GetOutput(), dir.File("p.exr"), o)) << o->Errors;
  // A bad OutputScalarType is an error and an empty image.
  o->Clear();
  o->Watch(asFloat);
  asFloat->SetOutputScalarType(VTK_INT);
  asFloat->Update();
  EXPECT_NE(o->Errors.find("OutputScalarType"), std::string::npos) << o->Errors;
  EXPECT_EQ(asFloat->GetOutput()->GetNumberOfPoints(), 0);
}

//------------------------------------------------------------------------------
TEST(ImageBake, SixteenBitTIFFDecalGivesItsOwnColours)
{
  // Left half and right half of the decal, 16-bit RGBA: no byte holds these values.
  // Their colours are value * 255 / 65535 rounded: (254, 1, 42) and (0, 129, 253); their
  // top bytes would give (255, 0, 42) and (0, 129, 254), their low bytes (0, 192, 128)
  // and (64, 96, 0).
  const unsigned short left[4] = { 0xFF00, 0x00C0, 0x2A80, 0xFFFF };
  const unsigned short right[4] = { 0x0040, 0x8160, 0xFE00, 0xFFFF };
  vtkSmartPointer<vtkImageData> image = MakeImage(
    16, 8, VTK_UNSIGNED_SHORT, 4, [&](int i, int, int c) { return i < 8 ? left[c] : right[c]; });
  ImageDirectory dir;
  vtkNew<MessageObserver> o;
  ASSERT_TRUE(WriteImage(image, dir.File("decal16.tif"), o)) << o->Errors;
  vtkNew<vtkOFBImageReader> reader;
  vtkSmartPointer<vtkImageData> decalImage = ReadImage(dir.File("decal16.tif"), o, reader);
  ASSERT_TRUE(o->Errors.empty()) << o->Errors;
  EXPECT_EQ(reader->GetFileBitsPerSample(), 16);
  auto* read = vtkUnsignedShortArray::SafeDownCast(decalImage->GetPointData()->GetScalars());
  ASSERT_NE(read, nullptr);
  ASSERT_EQ(read->GetNumberOfComponents(), 4);
  EXPECT_EQ(read->GetTypedComponent(0, 0), 0xFF00);
  EXPECT_EQ(read->GetTypedComponent(15, 1), 0x8160);

  // Stamped 1.0 x 0.5 on the plane z = 0 (its +x right).
  vtkSmartPointer<vtkPolyData> plane = MakeTexturedPlane(16);
  vtkSmartPointer<vtkOFB> ofb = Build(plane, 128);
  vtkNew<vtkOFBDecalPatch> decal;
  decal->SetInputData(plane);
  decal->SetCenter(0.0, 0.0, 0.0);
  decal->SetDirection(1.0, 0.0, 0.0);
  decal->SetWidth(1.0);
  decal->SetHeight(0.5);
  vtkNew<vtkOFBTextureProjector> projector;
  o->Watch(projector);
  projector->SetInputData(ofb);
  projector->SetMeshConnection(decal->GetOutputPort());
  projector->SetTextureData(decalImage);
  projector->InterpolateTextureOff();
  projector->RepeatTextureOff();
  projector->SetMaximumDistance(0.5);
  projector->Update();
  ASSERT_TRUE(o->Errors.empty()) << o->Errors;
  auto* colors = vtkUnsignedCharArray::SafeDownCast(
    projector->GetOutput()->GetSampleData()->GetArray(vtkOFB::ColorsArrayName()));
  ASSERT_NE(colors, nullptr);
  const unsigned char leftRGB[3] = { 254, 1, 42 }, rightRGB[3] = { 0, 129, 253 };
  vtkIdType onLeft = 0, onRight = 0;
  const double cell = ofb->GetCellSize();
  for (vtkIdType i = 0; i < ofb->GetNumberOfSamples(); ++i)
  {
    double x[3];
    ofb->GetSamplePosition(i, x);
    if (std::abs(x[1]) > 0.25 - 2 * cell || std::abs(x[0]) > 0.5 - 2 * cell ||
      std::abs(x[0]) < 2 * cell)
    {
      continue; // near an edge of the decal or its middle
    }
    const unsigned char* c = colors->GetPointer(4 * i);
    const unsigned char* expected = x[0] < 0.0 ? leftRGB : rightRGB;
    ASSERT_EQ(int(c[0]), int(expected[0])) << i;
    ASSERT_EQ(int(c[1]), int(expected[1])) << i;
    ASSERT_EQ(int(c[2]), int(expected[2])) << i;
    EXPECT_EQ(int(c[3]), 255) << i;
    ++(x[0] < 0.0 ? onLeft : onRight);
  }
  EXPECT_GT(onLeft, 500);
  EXPECT_GT(onRight, 500);
}

//------------------------------------------------------------------------------
TEST(ImageBake, FloatOpenEXRDecalIsClampedToItsRange)
{
  // Float texels are fractions in [0, 1]: 0.5 gives 128, 2.0 and -1.0 clamp.
  vtkSmartPointer<vtkImageData> image = MakeImage(
    4, 4, VTK_FLOAT, 3, [](int, int, int c) { return c == 0 ? 0.5 : (c == 1 ? 2.0 : -1.0); });
  ImageDirectory dir;
  ASSERT_TRUE(WriteImage(image, dir.File("decal.exr")));
  vtkSmartPointer<vtkImageData> decalImage = ReadImage(dir.File("decal.exr"));
  ASSERT_EQ(decalImage->GetScalarType(), VTK_FLOAT);
  vtkSmartPointer<vtkPolyData> plane = MakeTexturedPlane(8);
  vtkSmartPointer<vtkOFB> ofb = Build(plane, 64);
  vtkNew<vtkOFBTextureProjector> projector;
  projector->SetInputData(ofb);
  projector->SetMeshData(plane);
  projector->SetTextureData(decalImage);
  projector->Update();
  auto* colors = vtkUnsignedCharArray::SafeDownCast(
    projector->GetOutput()->GetSampleData()->GetArray(vtkOFB::ColorsArrayName()));
  ASSERT_NE(colors, nullptr);
  ASSERT_GT(projector->GetNumberOfProjectedSamples(), 0);
  for (vtkIdType i = 0; i < colors->GetNumberOfTuples(); ++i)
  {
    const unsigned char* c = colors->GetPointer(4 * i);
    ASSERT_EQ(int(c[0]), 128);
    ASSERT_EQ(int(c[1]), 255);
    ASSERT_EQ(int(c[2]), 0);
  }
  // Signed or double texels are refused with the types named.
  vtkNew<MessageObserver> o;
  o->Watch(projector);
  projector->SetTextureData(MakeImage(2, 2, VTK_DOUBLE, 3, [](int, int, int) { return 0.5; }));
  projector->Update();
  EXPECT_NE(o->Errors.find("unsigned short or float"), std::string::npos) << o->Errors;
  EXPECT_NE(o->Errors.find("not double"), std::string::npos) << o->Errors;
  EXPECT_EQ(projector->GetOutput()->GetNumberOfSamples(), 0);
}
