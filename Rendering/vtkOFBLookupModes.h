// Private header of vtkOFBPolyDataMapper: what the mapper knows of each lookup mode, in
// one table (a new mode is an enumerator of vtkOFBPolyDataMapper::LookupModes, a row
// here and its branch in shaders/vtkOFBLookupFS.glsl).
#ifndef vtkOFBLookupModes_h
#define vtkOFBLookupModes_h

#include "vtkOFBPolyDataMapper.h"

// Every lookup mode once: its name, the define that names it in the fragment shader
// (vtkOFBLookupFS.glsl tells these apart and refuses any other), and whether it reads the
// pyramid of coarser levels.
struct vtkOFBLookupModeInfo
{
  int Mode;
  const char* Name;
  const char* Define;
  bool Pyramid;
};
constexpr vtkOFBLookupModeInfo vtkOFBLookupModeInfos[] = {
  { vtkOFBPolyDataMapper::LOOKUP_NEAREST, "Nearest", "OFB_LOOKUP_NEAREST", false },
  { vtkOFBPolyDataMapper::LOOKUP_INVERSE_DISTANCE,
    "InverseDistance",
    "OFB_LOOKUP_INVERSE_DISTANCE",
    false },
  { vtkOFBPolyDataMapper::LOOKUP_MIPMAPPED, "Mipmapped", "OFB_LOOKUP_MIPMAPPED", true },
  { vtkOFBPolyDataMapper::LOOKUP_NEAREST_MIPMAPPED,
    "NearestMipmapped",
    "OFB_LOOKUP_NEAREST_MIPMAPPED",
    true },
  { vtkOFBPolyDataMapper::LOOKUP_SMOOTH, "Smooth", "OFB_LOOKUP_SMOOTH", true },
  // Resolved to Smooth or Nearest before the shader is made (never OFB_LOOKUP_MODE).
  { vtkOFBPolyDataMapper::LOOKUP_AUTOMATIC, "Automatic", "OFB_LOOKUP_AUTOMATIC", false },
};
static_assert(sizeof(vtkOFBLookupModeInfos) / sizeof(vtkOFBLookupModeInfos[0]) ==
    vtkOFBPolyDataMapper::NUMBER_OF_LOOKUP_MODES,
  "one vtkOFBLookupModeInfos entry per lookup mode");

// The entry of `mode`, or null when it is not a lookup mode.
inline const vtkOFBLookupModeInfo* vtkOFBFindLookupMode(int mode)
{
  for (const vtkOFBLookupModeInfo& info : vtkOFBLookupModeInfos)
  {
    if (info.Mode == mode)
    {
      return &info;
    }
  }
  return nullptr;
}

#endif
