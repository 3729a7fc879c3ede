// Helpers of the OFB::IOImage tests: a temporary directory, images of every sample type,
// and reading and writing through vtkOFBImageReader and vtkOFBImageWriter.
#ifndef vtkOFBImageTestHelpers_h
#define vtkOFBImageTestHelpers_h

#include "vtkOFBTempDirectory.h"
#include "vtkOFBTestUtilities.h"

#include "vtkDataArray.h"
#include "vtkImageData.h"
#include "vtkOFBImageReader.h"
#include "vtkOFBImageWriter.h"
#include "vtkPointData.h"
#include "vtksys/Directory.hxx"
#include "vtksys/SystemTools.hxx"

#include <gtest/gtest.h>

#include <string>

namespace vtkofbtest
{
/// A fresh directory for one image test, removed at the end of the test.
class ImageDirectory : public TempDirectory
{
public:
  ImageDirectory()
    : TempDirectory("vtkofb-image-")
  {
  }
};

/// A w x h image of `type` scalars with `nc` components, texel (i, j) component c set by
/// `value(i, j, c)`.
template<typename F>
vtkSmartPointer<vtkImageData> MakeImage(int w, int h, int type, int nc, F value)
{
  auto image = vtkSmartPointer<vtkImageData>::New();
  image->SetDimensions(w, h, 1);
  image->AllocateScalars(type, nc);
  vtkDataArray* s = image->GetPointData()->GetScalars();
  for (int j = 0; j < h; ++j)
  {
    for (int i = 0; i < w; ++i)
    {
      for (int c = 0; c < nc; ++c)
      {
        s->SetComponent(static_cast<vtkIdType>(j) * w + i, c, value(i, j, c));
      }
    }
  }
  return image;
}

/// Write `image` to `path`; the writer's errors in `errors`.
inline bool WriteImage(vtkImageData* image,
  const std::string& path,
  MessageObserver* errors = nullptr,
  bool half = false)
{
  vtkNew<vtkOFBImageWriter> writer;
  if (errors)
  {
    errors->Watch(writer);
  }
  writer->SetInputData(image);
  writer->SetFileName(path.c_str());
  writer->SetHalfFloat(half);
  return writer->Write() == 1;
}

/// The image at `path` (empty on failure); the reader's errors in `errors`.
inline vtkSmartPointer<vtkImageData> ReadImage(const std::string& path,
  MessageObserver* errors = nullptr,
  vtkOFBImageReader* reader = nullptr)
{
  vtkNew<vtkOFBImageReader> own;
  vtkOFBImageReader* r = reader ? reader : own.Get();
  if (errors)
  {
    errors->Watch(r);
  }
  r->SetFileName(path.c_str());
  r->Update();
  auto out = vtkSmartPointer<vtkImageData>::New();
  out->ShallowCopy(r->GetOutput());
  return out;
}
}

#endif
