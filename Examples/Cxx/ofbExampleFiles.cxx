#include "ofbExampleFiles.h"
#include "ofbExampleErrors.h"

#include "vtkAlgorithm.h"
#include "vtkErrorCode.h"
#include "vtkImageData.h"
#include "vtkNew.h"
#include "vtkOFBStagedFiles.h"
#include "vtkPNGWriter.h"
#include "vtkRenderWindow.h"
#include "vtkUnsignedCharArray.h"
#include "vtkWindowToImageFilter.h"

namespace
{
std::string NameOf(const std::string& path)
{
  return path.substr(path.find_last_of('/') + 1);
}
}

namespace ofbexample
{
bool EncodePNG(vtkImageData* image, std::string& bytes, std::string& message)
{
  vtkNew<FirstError> errors;
  vtkNew<vtkPNGWriter> writer;
  writer->AddObserver(vtkCommand::ErrorEvent, errors);
  writer->WriteToMemoryOn();
  writer->SetInputData(image);
  writer->Write();
  vtkUnsignedCharArray* result = writer->GetResult();
  if (errors->Count > 0 || writer->GetErrorCode() != vtkErrorCode::NoError || !result ||
    result->GetNumberOfValues() == 0)
  {
    message = "cannot encode the PNG" + errors->Suffix();
    return false;
  }
  bytes.assign(reinterpret_cast<const char*>(result->GetPointer(0)),
    static_cast<size_t>(result->GetNumberOfValues()));
  return true;
}

bool WritePNG(vtkAlgorithm* source, const std::string& path, std::string& message)
{
  vtkOFBStagedFiles files(path);
  const std::string name = NameOf(path);
  if (!files.Begin({ name }, message))
  {
    return false;
  }
  vtkNew<FirstError> errors;
  source->AddObserver(vtkCommand::ErrorEvent, errors);
  source->Update();
  source->RemoveObserver(errors);
  vtkImageData* image = vtkImageData::SafeDownCast(source->GetOutputDataObject(0));
  std::string bytes, problem;
  if (errors->Count > 0 || !image || !EncodePNG(image, bytes, problem))
  {
    message =
      "cannot write '" + path + "': " + (problem.empty() ? "no image" : problem) + errors->Suffix();
    return false;
  }
  return files.Write(name, bytes, message) && files.Commit({ name }, message);
}

bool WriteWindowPNG(vtkRenderWindow* window,
  const std::string& path,
  std::string& message,
  bool frontBuffer)
{
  vtkNew<vtkWindowToImageFilter> grab;
  grab->SetInput(window);
  grab->SetInputBufferTypeToRGB();
  grab->SetReadFrontBuffer(frontBuffer);
  return WritePNG(grab, path, message);
}
}
