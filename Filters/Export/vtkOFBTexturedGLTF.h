/**
 * @class   vtkOFBTexturedGLTF
 * @brief   A textured surface as glTF 2.0 text, its texture embedded
 *
 * vtkGLTFExporter writes a scene, not a data set: the surface becomes the one actor of a
 * renderer (never rendered) with the image as its texture (interpolated), scalars off,
 * and the exporter writes it with its normals and the image inline (a data URI), as one
 * string. The writers of a baked OFB texture (the applications' export, ParaView's
 * textured mesh writer) stage that string and rename it into place (vtkOFBStagedFiles).
 *
 * @sa vtkOFBTextureBaker vtkOFBTextureAtlas
 */
#ifndef vtkOFBTexturedGLTF_h
#define vtkOFBTexturedGLTF_h

#include "vtkOFBExportModule.h" // for export macro

#include <string> // for the text

class vtkCommand;
class vtkImageData;
class vtkPolyData;

class VTKOFBEXPORT_EXPORT vtkOFBTexturedGLTF
{
public:
  /**
   * `surface` (with texture coordinates) textured by `texture` (an RGB image) as glTF 2.0
   * text; "" when the exporter fails. `errors`, when given, observes the exporter's
   * error events.
   */
  static std::string WriteToString(vtkPolyData* surface,
    vtkImageData* texture,
    vtkCommand* errors = nullptr);
};

#endif
