/**
 * @file   vtkOFBPaintBlend.h
 * @brief  Private: the per-sample arithmetic of vtkOFBPaintKernel (falloff, blend, cone)
 *
 * Inline templates, so that the kernel's inner loop compiles the default falloffs and
 * blend mode in and chooses the others per sample.
 */

#ifndef vtkOFBPaintBlend_h
#define vtkOFBPaintBlend_h

#include "vtkOFBBrush.h"
#include "vtkOFBPaintKernel.h"

#include <algorithm>

namespace vtkofbpaint
{
inline unsigned char ToByte(float v)
{
  v = std::min(1.0f, std::max(0.0f, v));
  return static_cast<unsigned char>(v * 255.0f + 0.5f);
}

// The falloff at normalized distance x: Kind is the falloff when known when compiling
// (the brush's default Smooth and the particles' default Constant, inlined), -1 for
// any (vtkOFBPaintKernel::Falloff).
template<int Kind>
inline double FalloffOf(const vtkOFBPaintSettings& s, double x)
{
  if constexpr (Kind == vtkOFBBrush::Smooth)
  {
    if (!(x <= 1.0))
    {
      return 0.0;
    }
    const double t = 1.0 - std::max(x, 0.0);
    return t * t * (3.0 - 2.0 * t);
  }
  else if constexpr (Kind == vtkOFBBrush::Constant)
  {
    return x <= 1.0 ? 1.0 : 0.0;
  }
  else
  {
    return vtkOFBPaintKernel::Falloff(s, x);
  }
}

// vtkOFBPaintKernel::BlendColor; Mode is the blend mode when known when compiling
// (the default Mix), -1 for `mode`.
template<int Mode>
inline void Blend(const unsigned char dst[4],
  const float src[4],
  float g,
  int mode,
  const unsigned char initial[4],
  unsigned char out[4])
{
  const int m = Mode >= 0 ? Mode : mode;
  float d[4];
  for (int k = 0; k < 4; ++k)
  {
    d[k] = dst[k] * (1.0f / 255.0f);
  }
  const float a = g * src[3];
  float r[4] = { d[0], d[1], d[2], d[3] };
  switch (m)
  {
    case vtkOFBBrush::Mix: // source over destination
    {
      const float ao = a + d[3] * (1.0f - a);
      if (ao > 0.0f)
      {
        for (int k = 0; k < 3; ++k)
        {
          r[k] = (src[k] * a + d[k] * d[3] * (1.0f - a)) / ao;
        }
      }
      r[3] = ao;
      break;
    }
    case vtkOFBBrush::Erase: // back to the initial colour
      for (int k = 0; k < 4; ++k)
      {
        r[k] = d[k] + g * (initial[k] * (1.0f / 255.0f) - d[k]);
      }
      break;
    case vtkOFBBrush::EraseAlpha:
      r[3] = d[3] * (1.0f - g);
      break;
    default: // Add, Subtract, Multiply, Lighten, Darken
      for (int k = 0; k < 3; ++k)
      {
        float f;
        switch (m)
        {
          case vtkOFBBrush::Add:
            f = std::min(1.0f, d[k] + src[k]);
            break;
          case vtkOFBBrush::Subtract:
            f = std::max(0.0f, d[k] - src[k]);
            break;
          case vtkOFBBrush::Multiply:
            f = d[k] * src[k];
            break;
          case vtkOFBBrush::Lighten:
            f = std::max(d[k], src[k]);
            break;
          default:
            f = std::min(d[k], src[k]);
            break;
        }
        r[k] = d[k] + a * (f - d[k]);
      }
      r[3] = d[3] + (1.0f - d[3]) * a;
      break;
  }
  for (int k = 0; k < 4; ++k)
  {
    out[k] = ToByte(r[k]);
  }
}

// Whether normal n lies within the normal-aware cone around the unit normal nc.
inline bool Facing(const float* n, const float* nc, float cosMax)
{
  return !(n[0] * nc[0] + n[1] * nc[1] + n[2] * nc[2] < cosMax);
}
}

#endif
