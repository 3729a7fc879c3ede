// OFBPaint's decals (key 'k', the stroke file's `decal` command): an image stamped on the
// surface with vtkOFBDecalPatch and vtkOFBTextureProjector, written through the painter
// (vtkOFBPainter::SetSampleColors) so that undo takes it back like a stroke.
#ifndef ofbPaintDecal_h
#define ofbPaintDecal_h

#include "vtkNew.h"
#include "vtkSmartPointer.h"

#include <string>

class vtkImageData;
class vtkOFBDecalPatch;
class vtkOFBPainter;
class vtkPolyData;

namespace ofbpaint
{
class DecalStamper
{
public:
  DecalStamper();
  ~DecalStamper();

  /// The image to stamp: read from `path` (PNG, JPEG, ...); false with `message` if it
  /// cannot be read. Until then a built-in badge (an arrow along the decal's direction).
  bool LoadImage(const std::string& path, std::string& message);

  /**
   * Stamp the image on `surface` (the painter's OFB's surface), `size` wide and high along
   * the surface, centred at `centre`, its right along `right` (projected on the surface;
   * the camera's right keeps the image upright on screen).
   * Returns the samples changed, or -1 with `message` set.
   */
  long long Stamp(vtkPolyData* surface,
    vtkOFBPainter* painter,
    const double centre[3],
    const double right[3],
    double size,
    std::string& message);

private:
  vtkSmartPointer<vtkImageData> Image;
  vtkSmartPointer<vtkOFBDecalPatch> Patch; // keeps its surface's walker between stamps
};
}

#endif
