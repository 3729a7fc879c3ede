// ofbInstalled: a program built against an installed vtkOFB (Examples/Build/CMakeLists.txt,
// find_package(vtkofb)). It builds the OFB of a sphere on the CPU, queries it, writes it to an
// .ofb file and reads it back, and checks that the object factories are registered
// (vtk_module_autoinit: an OpenGL render window, the interactor's default style) and that the
// OFB mapper and picker take the OFB, and compares an image with itself by the image
// comparison of tests (OFB::TestingImage). It opens no window, so it runs without a display.
//
// Usage: ofbInstalled [file.ofb]   (default: ofbInstalled.ofb in the current directory)

#include "vtkIdList.h"
#include "vtkImageData.h"
#include "vtkInteractorObserver.h"
#include "vtkNew.h"
#include "vtkOFB.h"
#include "vtkOFBBuilder.h"
#include "vtkOFBImageComparison.h"
#include "vtkOFBPolyDataMapper.h"
#include "vtkOFBReader.h"
#include "vtkOFBSamplePicker.h"
#include "vtkOFBWriter.h"
#include "vtkRenderWindow.h"
#include "vtkRenderWindowInteractor.h"
#include "vtkSphereSource.h"

#include <iostream>
#include <string>

int main(int argc, char* argv[])
{
  const std::string fileName = argc > 1 ? argv[1] : "ofbInstalled.ofb";

  vtkNew<vtkSphereSource> sphere;
  sphere->SetRadius(1.0);
  sphere->SetThetaResolution(48);
  sphere->SetPhiResolution(24);

  vtkNew<vtkOFBBuilder> builder;
  builder->SetInputConnection(sphere->GetOutputPort());
  builder->SetResolution(128); // cells along the longest side of the box
  builder->SetBackendToCPU();  // no render window here
  builder->Update();
  vtkOFB* ofb = builder->GetOutput();
  if (ofb->GetNumberOfSamples() == 0)
  {
    std::cerr << "ofbInstalled: the builder made no samples\n";
    return 1;
  }

  // The sample nearest a point of the sphere lies within sqrt(3) cells of it.
  double x[3] = { 1.0, 0.0, 0.0 };
  const vtkIdType id = ofb->FindClosestSample(x);
  vtkNew<vtkIdList> near;
  ofb->FindSamplesInSphere(x, 3.0 * ofb->GetCellSize(), near);
  if (id < 0 || near->GetNumberOfIds() == 0)
  {
    std::cerr << "ofbInstalled: no sample near (1, 0, 0)\n";
    return 1;
  }

  vtkNew<vtkOFBWriter> writer;
  writer->SetInputData(ofb);
  writer->SetFileName(fileName.c_str());
  if (!writer->Write())
  {
    std::cerr << "ofbInstalled: cannot write " << fileName << "\n";
    return 1;
  }
  vtkNew<vtkOFBReader> reader;
  reader->SetFileName(fileName.c_str());
  reader->Update();
  if (reader->GetOutput()->GetNumberOfSamples() != ofb->GetNumberOfSamples())
  {
    std::cerr << "ofbInstalled: " << fileName << " read back differs\n";
    return 1;
  }

  // Without the OpenGL factories this is a plain vtkRenderWindow that cannot render, and
  // without InteractionStyle's the interactor's style is a vtkInteractorStyleSwitchBase that
  // does nothing. Creating them opens no display.
  vtkNew<vtkRenderWindow> window;
  vtkNew<vtkRenderWindowInteractor> interactor;
  vtkInteractorObserver* style = interactor->GetInteractorStyle();
  if (!window->IsA("vtkOpenGLRenderWindow") || !style || !style->IsA("vtkInteractorStyleSwitch"))
  {
    std::cerr << "ofbInstalled: the render window is a " << window->GetClassName()
              << " and the interactor style a " << (style ? style->GetClassName() : "null")
              << ": vtk_module_autoinit did not register the OpenGL and InteractionStyle "
                 "factories\n";
    return 1;
  }
  vtkNew<vtkOFBPolyDataMapper> mapper;
  mapper->SetInputConnection(sphere->GetOutputPort());
  mapper->SetOFB(reader->GetOutput());
  vtkNew<vtkOFBSamplePicker> picker;
  picker->SetOFB(reader->GetOutput());

  // A 64 x 64 texture on a black border, compared with itself: it passes.
  vtkNew<vtkImageData> image;
  image->SetDimensions(64, 64, 1);
  image->AllocateScalars(VTK_UNSIGNED_CHAR, 3);
  auto* pixels = static_cast<unsigned char*>(image->GetScalarPointer());
  for (int i = 0; i < 64 * 64; ++i)
  {
    const int x = i % 64;
    const int y = i / 64;
    const bool inside = x >= 8 && x < 56 && y >= 8 && y < 56;
    for (int c = 0; c < 3; ++c)
    {
      pixels[3 * i + c] = static_cast<unsigned char>(inside ? 40 + (x * 37 + y * 91) % 160 : 0);
    }
  }
  vtkNew<vtkOFBImageComparison> comparison;
  comparison->SetImage(image);
  comparison->SetBaseline(image);
  if (!comparison->Compare())
  {
    std::cerr << "ofbInstalled: an image differs from itself: " << comparison->GetErrorText()
              << "\n";
    return 1;
  }

  std::cout << "ofbInstalled: " << ofb->GetNumberOfSamples() << " samples (X "
            << ofb->GetNumberOfSamples(0) << ", Y " << ofb->GetNumberOfSamples(1) << ", Z "
            << ofb->GetNumberOfSamples(2) << "), " << near->GetNumberOfIds()
            << " within 3 cells of (1, 0, 0), written to and read from " << fileName
            << "; render window class " << window->GetClassName() << ", interactor style "
            << style->GetClassName() << "; image comparison passed (correlation "
            << comparison->GetCorrelation() << ")\n";
  return 0;
}
