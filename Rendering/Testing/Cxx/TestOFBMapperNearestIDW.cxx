// Image test: Nearest (left) against InverseDistance (right) lookups, close up on a
// sphere whose coarse OFB (64 cells) holds a random colour per sample: Nearest shows
// the sample mosaic, IDW blends it smoothly.
#include "vtkMinimalStandardRandomSequence.h"
#include "vtkNew.h"
#include "vtkOFB.h"
#include "vtkOFBMapperTestHelpers.h"
#include "vtkOFBTestUtilities.h"

int TestOFBMapperNearestIDW(int argc, char* argv[])
{
  vtkSmartPointer<vtkPolyData> sphere = vtkofbtest::MakeSphere(1.0, 32);
  vtkSmartPointer<vtkOFB> ofb = vtkofbtest::Build(sphere, 64);
  vtkNew<vtkMinimalStandardRandomSequence> random;
  random->SetSeed(7);
  vtkofbtest::Paint(ofb,
    [&](const double*, unsigned char rgba[4])
    {
      for (int i = 0; i < 3; ++i)
      {
        random->Next();
        rgba[i] = static_cast<unsigned char>(40 + 200 * random->GetValue());
      }
      rgba[3] = 255;
    });

  const double background[3] = { 0.1, 0.1, 0.1 };
  return vtkofbtest::CompareLookupModes(argc,
    argv,
    sphere,
    ofb,
    vtkOFBPolyDataMapper::LOOKUP_NEAREST,
    vtkOFBPolyDataMapper::LOOKUP_INVERSE_DISTANCE,
    background,
    1.8);
}
