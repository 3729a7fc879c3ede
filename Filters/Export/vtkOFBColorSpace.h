// Private header of vtkOFBMapToColors: the HSL lightness of an RGB colour and the colour
// with another lightness (hue and saturation kept), for VTK surface LIC's contrast
// enhancement of the final colour. shaders/vtkOFBLookupFS.glsl has the same two functions.
#ifndef vtkOFBColorSpace_h
#define vtkOFBColorSpace_h

#include <glm/glm.hpp>

#include <algorithm>
#include <cmath>

/// HSL lightness of rgb (components in [0, 1]): the mean of its largest and smallest.
inline float vtkOFBLightness(const glm::vec3& rgb)
{
  return 0.5f * (std::max({ rgb.r, rgb.g, rgb.b }) + std::min({ rgb.r, rgb.g, rgb.b }));
}

/// rgb with HSL lightness `l` and its hue and saturation: each channel is
/// l + C (k - 1/2), where k = (channel - min) / (max - min) depends on the hue alone and the
/// chroma C = (1 - |2 l - 1|) S keeps the saturation S.
inline glm::vec3 vtkOFBWithLightness(const glm::vec3& rgb, float l)
{
  const float high = std::max({ rgb.r, rgb.g, rgb.b });
  const float low = std::min({ rgb.r, rgb.g, rgb.b });
  const float chroma = high - low;
  const float lightness = 0.5f * (high + low);
  const float room = 1.0f - std::abs(2.0f * lightness - 1.0f);
  if (!(chroma > 0.0f) || !(room > 0.0f))
  {
    return glm::vec3(l);
  }
  const float saturation = std::min(1.0f, chroma / room);
  const float chroma2 = (1.0f - std::abs(2.0f * l - 1.0f)) * saturation;
  return glm::clamp(glm::vec3(l) + chroma2 * ((rgb - low) / chroma - 0.5f), 0.0f, 1.0f);
}

#endif
