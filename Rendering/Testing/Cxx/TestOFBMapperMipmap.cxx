// Image test: a far view of a sphere painted with a checker of 2-cell squares, without
// mipmaps (left, InverseDistance: aliasing) and with them (right, Mipmapped: the pattern
// averages out to the mean colour).
#include "vtkNew.h"
#include "vtkOFB.h"
#include "vtkOFBMapperTestHelpers.h"
#include "vtkOFBTestUtilities.h"

int TestOFBMapperMipmap(int argc, char* argv[])
{
  vtkSmartPointer<vtkPolyData> sphere = vtkofbtest::MakeSphere(1.0, 32);
  vtkSmartPointer<vtkOFB> ofb = vtkofbtest::Build(sphere, 512);
  const unsigned char black[4] = { 20, 20, 20, 255 };
  const unsigned char yellow[4] = { 250, 220, 40, 255 };
  vtkofbtest::PaintChecker(ofb, 2.0 * ofb->GetCellSize(), black, yellow);

  const double background[3] = { 0.3, 0.3, 0.4 };
  return vtkofbtest::CompareLookupModes(argc,
    argv,
    sphere,
    ofb,
    vtkOFBPolyDataMapper::LOOKUP_INVERSE_DISTANCE,
    vtkOFBPolyDataMapper::LOOKUP_MIPMAPPED,
    background,
    0.5);
}
