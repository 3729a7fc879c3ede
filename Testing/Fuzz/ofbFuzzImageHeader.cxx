// Fuzz target: the example applications' one image reader (Examples/Cxx/ofbExampleImage.cxx,
// ReadImageChecked), which checks a PNG, JPEG, BMP or binary PNM file before a decoder
// allocates and then decodes it, and those and TIFF, OpenEXR and Radiance HDR files, with
// vtkOFBImageReader (OpenImageIO). An input may be refused with a message; it must not
// crash, and an image it accepts has the size and scalars the checks promise.
#include "ofbExampleImage.h"
#include "ofbFuzzFile.h"

#include "vtkDataArray.h"
#include "vtkImageData.h"
#include "vtkObject.h"
#include "vtkPointData.h"

#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <string>

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size)
{
  vtkObject::GlobalWarningDisplayOff();
  const std::string& path = ofbFuzzWriteInput("ofb-fuzz-image", ".img", data, size);

  // A small pixel limit keeps each run short; the checks are the same at any limit.
  std::string message;
  vtkSmartPointer<vtkImageData> image = ofbexample::ReadImageChecked(path, 1 << 20, message);
  if (image)
  {
    int dims[3];
    image->GetDimensions(dims);
    vtkDataArray* scalars = image->GetPointData()->GetScalars();
    const int type = scalars ? scalars->GetDataType() : 0;
    if (dims[0] < 1 || dims[1] < 1 || static_cast<long long>(dims[0]) * dims[1] > (1 << 20) ||
      !scalars || scalars->GetNumberOfTuples() != static_cast<vtkIdType>(dims[0]) * dims[1] ||
      scalars->GetNumberOfComponents() < 1 || scalars->GetNumberOfComponents() > 4 ||
      (type != VTK_UNSIGNED_CHAR && type != VTK_UNSIGNED_SHORT && type != VTK_FLOAT))
    {
      std::fprintf(stderr, "ofbFuzzImageHeader: an accepted image breaks the checks\n");
      std::abort();
    }
  }
  else if (message.empty())
  {
    std::fprintf(stderr, "ofbFuzzImageHeader: a refusal without a message\n");
    std::abort();
  }
  return 0;
}
