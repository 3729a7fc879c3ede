// ofbPaintCheckImage: count the pixels of a PNG whose colour is dominated by one channel,
// for the test of OFBPaint's headless mode (does the picture show the paint?).
//
// Usage: ofbPaintCheckImage IMAGE.png red|green|blue MIN [MAX [X0 X1]]
//
// A pixel counts when its channel is at least 60 and at least 1.8 times each of the other
// two (shaded paint of that colour; not the grey background, nor white or grey surface).
// Exits 0 when the count is in [MIN, MAX] (MAX default unbounded, -1 for unbounded with
// X0 X1), 1 otherwise. With X0 X1 only the pixel columns [X0, X1) count.
#include "ofbExampleImage.h"

#include "vtkImageData.h"
#include "vtkPointData.h"
#include "vtkUnsignedCharArray.h"

#include <cstdlib>
#include <iostream>
#include <string>

int main(int argc, char* argv[])
{
  if (argc < 4 || argc == 6 || argc > 7)
  {
    std::cerr << "Usage: " << argv[0] << " IMAGE.png red|green|blue MIN [MAX [X0 X1]]\n";
    return EXIT_FAILURE;
  }
  const std::string channelName = argv[2];
  const int channel =
    channelName == "red" ? 0 : (channelName == "green" ? 1 : (channelName == "blue" ? 2 : -1));
  const long long low = std::atoll(argv[3]);
  const long long high = argc >= 5 ? std::atoll(argv[4]) : -1;
  const long long x0 = argc == 7 ? std::atoll(argv[5]) : 0;
  const long long x1 = argc == 7 ? std::atoll(argv[6]) : -1;
  std::string message;
  vtkSmartPointer<vtkImageData> image = channel < 0
    ? nullptr
    : ofbexample::ReadImageChecked(argv[1], ofbexample::DefaultMaximumImagePixels, message);
  if (!image)
  {
    std::cerr << "ofbPaintCheckImage: "
              << (channel < 0 ? "bad channel '" + channelName + "'" : message) << "\n";
    return EXIT_FAILURE;
  }
  auto* pixels = vtkUnsignedCharArray::SafeDownCast(image->GetPointData()->GetScalars());
  if (!pixels || pixels->GetNumberOfComponents() < 3)
  {
    std::cerr << "ofbPaintCheckImage: '" << argv[1] << "' is not an RGB image\n";
    return EXIT_FAILURE;
  }
  long long count = 0;
  const long long width = image->GetDimensions()[0];
  for (vtkIdType i = 0; i < pixels->GetNumberOfTuples(); ++i)
  {
    const long long x = i % width;
    if (x < x0 || (x1 >= 0 && x >= x1))
    {
      continue;
    }
    const double c = pixels->GetTypedComponent(i, channel);
    const double o1 = pixels->GetTypedComponent(i, (channel + 1) % 3);
    const double o2 = pixels->GetTypedComponent(i, (channel + 2) % 3);
    count += c >= 60.0 && c >= 1.8 * o1 && c >= 1.8 * o2;
  }
  const bool ok = count >= low && (high < 0 || count <= high);
  std::cout << argv[1] << ": " << count << " " << channelName << " pixels of "
            << pixels->GetNumberOfTuples() << " (expected " << low << " to "
            << (high < 0 ? std::string("any") : std::to_string(high)) << ")\n";
  return ok ? EXIT_SUCCESS : EXIT_FAILURE;
}
