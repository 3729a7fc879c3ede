#include "ofbPaintDecal.h"
#include "ofbPaintErrors.h"

#include "ofbExampleImage.h"

#include "vtkCommand.h"
#include "vtkIdTypeArray.h"
#include "vtkImageData.h"
#include "vtkOFB.h"
#include "vtkOFBDecalPatch.h"
#include "vtkOFBPainter.h"
#include "vtkOFBTextureProjector.h"
#include "vtkPointData.h"
#include "vtkPolyData.h"
#include "vtkUnsignedCharArray.h"

#include <cmath>
#include <cstring>

namespace
{
/// A 128 x 128 RGBA badge, transparent around its disc: a blue ring, a yellow disc and a
/// red arrow pointing up (+v).
vtkSmartPointer<vtkImageData> Badge()
{
  const int n = 128;
  auto image = vtkSmartPointer<vtkImageData>::New();
  image->SetDimensions(n, n, 1);
  image->AllocateScalars(VTK_UNSIGNED_CHAR, 4);
  auto* texels = vtkUnsignedCharArray::SafeDownCast(image->GetPointData()->GetScalars());
  for (int j = 0; j < n; ++j)
  {
    for (int i = 0; i < n; ++i)
    {
      const double x = (i + 0.5) / n * 2.0 - 1.0, y = (j + 0.5) / n * 2.0 - 1.0;
      const double r = std::hypot(x, y);
      const bool arrow = (y > -0.5 && y < 0.6 && std::abs(x) < 0.42 * (0.6 - y) / 1.1) ||
        (y > -0.55 && y < 0.0 && std::abs(x) < 0.12);
      unsigned char c[4] = { 0, 0, 0, 0 };
      if (r < 0.78)
      {
        const unsigned char fill[4] = { 250, 200, 40, 255 }, red[4] = { 200, 30, 30, 255 };
        std::memcpy(c, arrow ? red : fill, 4);
      }
      else if (r < 1.0)
      {
        const unsigned char ring[4] = { 20, 40, 120, 255 };
        std::memcpy(c, ring, 4);
      }
      texels->SetTypedTuple(static_cast<vtkIdType>(j) * n + i, c);
    }
  }
  return image;
}
}

namespace ofbpaint
{
DecalStamper::DecalStamper()
  : Image(Badge())
  , Patch(vtkSmartPointer<vtkOFBDecalPatch>::New())
{
  this->Patch->SetResolution(48, 48);
}

DecalStamper::~DecalStamper() = default;

bool DecalStamper::LoadImage(const std::string& path, std::string& message)
{
  vtkSmartPointer<vtkImageData> image =
    ofbexample::ReadImageChecked(path, ofbexample::DefaultMaximumImagePixels, message);
  if (image)
  {
    this->Image = image;
  }
  return image != nullptr;
}

long long DecalStamper::Stamp(vtkPolyData* surface,
  vtkOFBPainter* painter,
  const double centre[3],
  const double right[3],
  double size,
  std::string& message)
{
  vtkOFB* ofb = painter->GetOFB();
  vtkNew<FirstError> errors;
  this->Patch->AddObserver(vtkCommand::ErrorEvent, errors);
  this->Patch->SetInputData(surface);
  this->Patch->SetCenter(centre[0], centre[1], centre[2]);
  this->Patch->SetDirection(right[0], right[1], right[2]);
  this->Patch->SetWidth(size);
  this->Patch->SetHeight(size);
  vtkNew<vtkOFBTextureProjector> projector;
  projector->AddObserver(vtkCommand::ErrorEvent, errors);
  projector->SetInputData(ofb);
  projector->SetMeshConnection(this->Patch->GetOutputPort());
  projector->SetTextureData(this->Image);
  projector->RepeatTextureOff();
  projector->SetMaximumDistance(1.0);
  projector->Update();
  this->Patch->RemoveObservers(vtkCommand::ErrorEvent);
  vtkOFB* stamped = projector->GetOutput();
  auto* before = vtkUnsignedCharArray::SafeDownCast(ofb->GetSampleData()->GetArray("Colors"));
  auto* after = vtkUnsignedCharArray::SafeDownCast(stamped->GetSampleData()->GetArray("Colors"));
  if (!errors->Text.empty() || !after || stamped->GetNumberOfSamples() != ofb->GetNumberOfSamples())
  {
    message = "cannot stamp the decal" + (errors->Text.empty() ? "" : ": " + errors->Text);
    return -1;
  }
  // Only the samples the decal changed go through the painter (one undo step).
  vtkNew<vtkIdTypeArray> ids;
  vtkNew<vtkUnsignedCharArray> colors;
  colors->SetNumberOfComponents(4);
  for (vtkIdType i = 0; i < ofb->GetNumberOfSamples(); ++i)
  {
    const unsigned char* c = after->GetPointer(4 * i);
    if (!before || std::memcmp(before->GetPointer(4 * i), c, 4) != 0)
    {
      ids->InsertNextValue(i);
      colors->InsertNextTypedTuple(c);
    }
  }
  return painter->SetSampleColors(ids, colors);
}
}
