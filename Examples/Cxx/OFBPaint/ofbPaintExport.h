// OFBPaint's export of a painting to files other programs read (key 'x', --export):
// a textured OBJ or glTF (the paint baked into the mesh's UV texture by vtkOFBTextureBaker,
// or, for a mesh without texture coordinates, into a texture atlas of charts laid out by
// vtkOFBTextureAtlas),
// a PLY with vertex colours or a VTP with every sample array as point arrays (both
// through vtkOFBProbeFilter).
#ifndef ofbPaintExport_h
#define ofbPaintExport_h

#include "vtkSmartPointer.h"

#include <string>

class vtkOFB;
class vtkPolyData;

namespace ofbpaint
{
/// The default export file of a mesh: <mesh name>_<what>.obj in the working directory
/// (an OBJ: every mesh can have its colours baked into a texture).
std::string DefaultExportPath(const std::string& meshPath, const std::string& what);

/**
 * Write the paint of `ofb` on `surface` to `path` by its extension: .obj (the surface with
 * its texture coordinates, a .mtl and the paint baked into a `textureSize` x `textureSize`
 * .png beside it; a surface without texture coordinates is written with those of a
 * vtkOFBTextureAtlas, a texel a cell where the atlas fits `textureSize` texels a side,
 * and the texture has the atlas's size), .gltf (the same textured surface with its normals
 * as glTF 2.0, the image embedded, by vtkGLTFExporter), .ply (vertex colours) or .vtp
 * (every sample array). Every file is written as ofbExampleFiles.h says: staged beside its
 * target, checked, then renamed over it, so a failure (a full disk, a directory in the
 * way) or a kill leaves the previous export as it was and no temporary file behind. The
 * .mtl names the texture by its file name alone. Returns false with `message` the reason;
 * true with `message` saying what was written.
 */
bool ExportPainting(vtkPolyData* surface,
  vtkOFB* ofb,
  const std::string& path,
  int textureSize,
  std::string& message);

/**
 * The way in (--import-texture): `ofb` with the texture image at `imagePath` (read by
 * ofbexample::ReadImageChecked) projected into its colours through the
 * surface's texture coordinates (vtkOFBTextureProjector). Null with `message` the reason.
 */
vtkSmartPointer<vtkOFB> ImportTexture(vtkPolyData* surface,
  vtkOFB* ofb,
  const std::string& imagePath,
  std::string& message);

}

#endif
