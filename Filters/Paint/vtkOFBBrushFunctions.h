/**
 * @file   vtkOFBBrushFunctions.h
 * @brief  Private: the falloff formulas and blend functions of vtkOFBBrush, written once
 *
 * vtkOFBBrush::EvaluateFalloff and vtkOFBPaintKernel (the per-sample work of
 * vtkOFBPainter) both use these. They are inline templates, so that the kernel's inner
 * loop compiles in a falloff or blend mode known when compiling (the switch on a constant
 * folds away) and otherwise switches per sample, without a virtual call.
 *
 * Each switch names every enumerator and has no default: an enumerator added without
 * its formula is a compiler warning (-Wswitch). A value that is no enumerator, which
 * vtkOFBBrush's setters refuse with an error, gives a falloff of 0 and leaves colours
 * unchanged.
 */

#ifndef vtkOFBBrushFunctions_h
#define vtkOFBBrushFunctions_h

#include "vtkOFBBrush.h"

#include <algorithm>
#include <cmath>

namespace vtkofbbrush
{
/**
 * F(x) of falloff `kind` at the normalized distance x (see vtkOFBBrush): 0 for x > 1 or
 * NaN, F(0) for x < 0. `custom(x)` gives the Custom curve at x in [0, 1] (the brush's
 * vtkPiecewiseFunction, or the kernel's table of it).
 */
template<class CustomCurve>
inline double Falloff(vtkOFBBrush::FalloffType kind, double x, const CustomCurve& custom)
{
  if (!(x <= 1.0))
  {
    return 0.0; // outside the support, or NaN
  }
  x = std::max(x, 0.0);
  const double t = 1.0 - x;
  switch (kind)
  {
    case vtkOFBBrush::FALLOFF_CONSTANT:
      return 1.0;
    case vtkOFBBrush::FALLOFF_LINEAR:
      return t;
    case vtkOFBBrush::FALLOFF_SMOOTH:
      return t * t * (3.0 - 2.0 * t);
    case vtkOFBBrush::FALLOFF_SPHERE:
      return std::sqrt(std::max(0.0, 1.0 - x * x));
    case vtkOFBBrush::FALLOFF_ROOT:
      return std::sqrt(t);
    case vtkOFBBrush::FALLOFF_SHARP:
      return t * t;
    case vtkOFBBrush::FALLOFF_GAUSSIAN:
      return std::exp(-4.5 * x * x); // sigma = 1/3
    case vtkOFBBrush::FALLOFF_CUSTOM:
      return custom(x);
    case vtkOFBBrush::NUMBER_OF_FALLOFFS:
      break;
  }
  return 0.0; // not a falloff
}

/// A colour component in [0, 1] as a byte, rounded.
inline unsigned char ToByte(float v)
{
  v = std::min(1.0f, std::max(0.0f, v));
  return static_cast<unsigned char>(v * 255.0f + 0.5f);
}

/**
 * The blend modes that work component by component (Add to Darken): the component that
 * destination component d and source component s give at full weight. Other modes: d.
 */
inline float BlendComponent(vtkOFBBrush::BlendModeType mode, float d, float s)
{
  switch (mode)
  {
    case vtkOFBBrush::BLEND_ADD:
      return std::min(1.0f, d + s);
    case vtkOFBBrush::BLEND_SUBTRACT:
      return std::max(0.0f, d - s);
    case vtkOFBBrush::BLEND_MULTIPLY:
      return d * s;
    case vtkOFBBrush::BLEND_LIGHTEN:
      return std::max(d, s);
    case vtkOFBBrush::BLEND_DARKEN:
      return std::min(d, s);
    case vtkOFBBrush::BLEND_MIX:
    case vtkOFBBrush::BLEND_ERASE:
    case vtkOFBBrush::BLEND_ERASE_ALPHA:
    case vtkOFBBrush::NUMBER_OF_BLEND_MODES:
      break;
  }
  return d;
}

/**
 * Blend a colour `dst` (bytes) with the source `src` (RGBA in [0, 1]) by the weight g
 * (falloff times strength) into `out` (see vtkOFBBrush for the modes); `initial` is the
 * sample's initial colour (used by Erase only). Mode is the blend mode when known when
 * compiling (the default Mix), -1 for `mode`.
 */
template<int Mode>
inline void Blend(const unsigned char dst[4],
  const float src[4],
  float g,
  vtkOFBBrush::BlendModeType mode,
  const unsigned char initial[4],
  unsigned char out[4])
{
  const vtkOFBBrush::BlendModeType m =
    Mode >= 0 ? static_cast<vtkOFBBrush::BlendModeType>(Mode) : mode;
  float d[4];
  for (int k = 0; k < 4; ++k)
  {
    d[k] = dst[k] * (1.0f / 255.0f);
  }
  const float a = g * src[3];
  float r[4] = { d[0], d[1], d[2], d[3] };
  switch (m)
  {
    case vtkOFBBrush::BLEND_MIX: // source over destination
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
    case vtkOFBBrush::BLEND_ERASE: // back to the initial colour
      for (int k = 0; k < 4; ++k)
      {
        r[k] = d[k] + g * (initial[k] * (1.0f / 255.0f) - d[k]);
      }
      break;
    case vtkOFBBrush::BLEND_ERASE_ALPHA:
      r[3] = d[3] * (1.0f - g);
      break;
    case vtkOFBBrush::BLEND_ADD:
    case vtkOFBBrush::BLEND_SUBTRACT:
    case vtkOFBBrush::BLEND_MULTIPLY:
    case vtkOFBBrush::BLEND_LIGHTEN:
    case vtkOFBBrush::BLEND_DARKEN:
      for (int k = 0; k < 3; ++k)
      {
        r[k] = d[k] + a * (BlendComponent(m, d[k], src[k]) - d[k]);
      }
      r[3] = d[3] + (1.0f - d[3]) * a;
      break;
    case vtkOFBBrush::NUMBER_OF_BLEND_MODES:
      break; // not a blend mode: unchanged
  }
  for (int k = 0; k < 4; ++k)
  {
    out[k] = ToByte(r[k]);
  }
}

/// Whether normal n lies within the normal-aware cone around the unit normal nc.
inline bool Facing(const float* n, const float* nc, float cosMax)
{
  return !(n[0] * nc[0] + n[1] * nc[1] + n[2] * nc[2] < cosMax);
}
}

#endif
