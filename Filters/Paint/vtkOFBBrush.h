/**
 * @class   vtkOFBBrush
 * @brief   A volume brush for painting a vtkOFB: radius, colour, strength, falloff, blend
 *
 * vtkOFBBrush describes one dab of the spherical volume brush of the paper
 * "Sample-based Surface Coloring" (section 5): every sample P of the OFB within
 * `Radius` of the dab centre C is blended with the brush colour by the weight
 *
 *   G = Strength * F(|P - C| / Radius)   (paper Eq. 2, support m = Radius)
 *
 * where F is the falloff over the normalized distance x in [0, 1]:
 *
 *   Constant  F = 1
 *   Linear    F = 1 - x
 *   Smooth    F = 3t^2 - 2t^3, t = 1 - x      (smoothstep)
 *   Sphere    F = sqrt(1 - x^2)
 *   Root      F = sqrt(1 - x)
 *   Sharp     F = (1 - x)^2
 *   Gaussian  F = exp(-x^2 / (2 sigma^2)), sigma = 1/3 (F(1) = exp(-4.5), about 0.011)
 *   Custom    F = the vtkPiecewiseFunction given to SetCustomFalloff at x, clamped to [0, 1]
 *
 * The blend modes say what the weight G does to a sample's RGBA colour Cd
 * (components in [0, 1]) with the brush colour Cb (alpha ab); `a = G * ab`:
 *
 *   Mix        "over" compositing of the brush colour with opacity a: on an opaque
 *              sample RGB = lerp(Cd, Cb, a), the paper's Eq. 1; a transparent sample
 *              takes the brush colour and alpha a (the reveal of the paper's Fig. 2).
 *   Add        RGB = lerp(Cd, min(Cd + Cb, 1), a)
 *   Subtract   RGB = lerp(Cd, max(Cd - Cb, 0), a)
 *   Multiply   RGB = lerp(Cd, Cd * Cb, a)
 *   Lighten    RGB = lerp(Cd, max(Cd, Cb), a)
 *   Darken     RGB = lerp(Cd, min(Cd, Cb), a)
 *              (Add to Darken: alpha = Ad + (1 - Ad) * a, so paint reveals as Mix does)
 *   Erase      RGBA = lerp(Cd, C0, G): back to the sample's initial colour C0 (see
 *              vtkOFBPainter); the brush colour is not used.
 *   EraseAlpha alpha = Ad * (1 - G); RGB unchanged.
 *
 * The target says what the dab paints: `TARGET_COLOR` (the "Colors" sample array),
 * `TARGET_NORMAL` (bumps in the "Normals" sample array, paper section 9.2.1, rendered by
 * vtkOFBPolyDataMapper with UsePaintedNormals) or `TARGET_SMEAR` (the colour carried
 * from the previous dab position of a stroke, paper Eq. 3 and section 6.2.2).
 *
 * The falloff formulas and blend functions are written once, in the private header
 * vtkOFBBrushFunctions.h, which EvaluateFalloff and vtkOFBPainter's kernel both use.
 * The setters refuse a value that is not one of the enumerators, with an error, and
 * keep the previous setting.
 *
 * A brush is a description only; vtkOFBPainter (and through it vtkOFBPaintFilter and
 * vtkOFBParticleAdvector) applies it.
 *
 * @sa vtkOFBPainter vtkOFBPaintFilter
 */

#ifndef vtkOFBBrush_h
#define vtkOFBBrush_h

#include "vtkOFBPaintModule.h" // for export macro
#include "vtkObject.h"
#include "vtkSmartPointer.h" // for member

class vtkOFB;
class vtkPiecewiseFunction;

class VTKOFBPAINT_EXPORT vtkOFBBrush : public vtkObject
{
public:
  static vtkOFBBrush* New();
  vtkTypeMacro(vtkOFBBrush, vtkObject);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  /// Falloff curves F over the normalized distance (see the class description).
  /// NUMBER_OF_FALLOFFS counts them (not a falloff).
  enum FalloffType
  {
    FALLOFF_CONSTANT = 0,
    FALLOFF_LINEAR,
    FALLOFF_SMOOTH,
    FALLOFF_SPHERE,
    FALLOFF_ROOT,
    FALLOFF_SHARP,
    FALLOFF_GAUSSIAN,
    FALLOFF_CUSTOM,
    NUMBER_OF_FALLOFFS
  };

  /// Blend modes (see the class description). NUMBER_OF_BLEND_MODES counts them.
  enum BlendModeType
  {
    BLEND_MIX = 0,
    BLEND_ADD,
    BLEND_SUBTRACT,
    BLEND_MULTIPLY,
    BLEND_LIGHTEN,
    BLEND_DARKEN,
    BLEND_ERASE,
    BLEND_ERASE_ALPHA,
    NUMBER_OF_BLEND_MODES
  };

  /// What a dab paints. NUMBER_OF_TARGETS counts them.
  enum TargetType
  {
    TARGET_COLOR = 0,
    TARGET_NORMAL,
    TARGET_SMEAR,
    NUMBER_OF_TARGETS
  };

  ///@{
  /**
   * Radius of the brush sphere in world units (> 0; default 1.0). The painter
   * refuses dabs whose radius is not positive and finite.
   */
  vtkSetMacro(Radius, double);
  vtkGetMacro(Radius, double);
  ///@}

  /**
   * Set the radius in cells of `ofb` (radius = cells * ofb->GetCellSize()). Does
   * nothing, with an error, when `ofb` is null or empty.
   */
  void SetRadiusInCells(double cells, vtkOFB* ofb);

  ///@{
  /**
   * Brush colour, RGBA in [0, 1] (default opaque white). SetColor(r, g, b) keeps
   * the opacity, as vtkProperty::SetColor does; SetOpacity sets the alpha alone.
   */
  vtkSetVector4Macro(Color, double);
  vtkGetVector4Macro(Color, double);
  void SetColor(double r, double g, double b);
  void SetOpacity(double a);
  double GetOpacity() const { return this->Color[3]; }
  ///@}

  ///@{
  /**
   * Strength, a factor in [0, 1] on the falloff (default 1).
   */
  vtkSetClampMacro(Strength, double, 0.0, 1.0);
  vtkGetMacro(Strength, double);
  ///@}

  ///@{
  /**
   * Falloff curve, a FalloffType (default FALLOFF_SMOOTH). Another value is an error
   * and leaves the falloff unchanged. GetFalloffAsString gives "Unknown" for a value
   * that is not a falloff.
   */
  void SetFalloff(int falloff);
  vtkGetMacro(Falloff, int);
  void SetFalloffToConstant() { this->SetFalloff(FALLOFF_CONSTANT); }
  void SetFalloffToLinear() { this->SetFalloff(FALLOFF_LINEAR); }
  void SetFalloffToSmooth() { this->SetFalloff(FALLOFF_SMOOTH); }
  void SetFalloffToSphere() { this->SetFalloff(FALLOFF_SPHERE); }
  void SetFalloffToRoot() { this->SetFalloff(FALLOFF_ROOT); }
  void SetFalloffToSharp() { this->SetFalloff(FALLOFF_SHARP); }
  void SetFalloffToGaussian() { this->SetFalloff(FALLOFF_GAUSSIAN); }
  void SetFalloffToCustom() { this->SetFalloff(FALLOFF_CUSTOM); }
  static const char* GetFalloffAsString(int falloff);
  ///@}

  ///@{
  /**
   * The curve of the Custom falloff: values over x in [0, 1], clamped to [0, 1]
   * (default none: the Custom falloff is then constant 1). Setting one does not
   * change the Falloff setting.
   */
  void SetCustomFalloff(vtkPiecewiseFunction* f);
  vtkPiecewiseFunction* GetCustomFalloff() const;
  ///@}

  /**
   * F(x) of the current falloff at the normalized distance `x` = distance/radius:
   * 0 for x > 1 or NaN, F(0) for x < 0.
   */
  double EvaluateFalloff(double normalizedDistance) const;

  /**
   * F(x) of falloff `falloff` (Custom uses `custom`, constant 1 when null); 0 for a
   * value that is not a falloff.
   */
  static double EvaluateFalloff(int falloff, double x, vtkPiecewiseFunction* custom = nullptr);

  ///@{
  /**
   * Blend mode, a BlendModeType (default BLEND_MIX). Another value is an error and
   * leaves the blend mode unchanged.
   */
  void SetBlendMode(int mode);
  vtkGetMacro(BlendMode, int);
  void SetBlendModeToMix() { this->SetBlendMode(BLEND_MIX); }
  void SetBlendModeToAdd() { this->SetBlendMode(BLEND_ADD); }
  void SetBlendModeToSubtract() { this->SetBlendMode(BLEND_SUBTRACT); }
  void SetBlendModeToMultiply() { this->SetBlendMode(BLEND_MULTIPLY); }
  void SetBlendModeToLighten() { this->SetBlendMode(BLEND_LIGHTEN); }
  void SetBlendModeToDarken() { this->SetBlendMode(BLEND_DARKEN); }
  void SetBlendModeToErase() { this->SetBlendMode(BLEND_ERASE); }
  void SetBlendModeToEraseAlpha() { this->SetBlendMode(BLEND_ERASE_ALPHA); }
  static const char* GetBlendModeAsString(int mode);
  ///@}

  ///@{
  /**
   * Target, a TargetType (default TARGET_COLOR). Another value is an error and leaves
   * the target unchanged.
   */
  void SetTarget(int target);
  vtkGetMacro(Target, int);
  void SetTargetToColor() { this->SetTarget(TARGET_COLOR); }
  void SetTargetToNormal() { this->SetTarget(TARGET_NORMAL); }
  void SetTargetToSmear() { this->SetTarget(TARGET_SMEAR); }
  static const char* GetTargetAsString(int target);
  ///@}

  ///@{
  /**
   * Smear target: how much of the colour carried from the previous dab position
   * replaces the brush colour, S = lerp(Cb, Cprev, SmearAmount), in [0, 1]
   * (default 1: pure smear, the brush colour unused). Paper Eq. 3.
   */
  vtkSetClampMacro(SmearAmount, double, 0.0, 1.0);
  vtkGetMacro(SmearAmount, double);
  ///@}

  ///@{
  /**
   * Normal target: bump depth, dimensionless, in [-1000, 1000] (default 0.5). A
   * sample's normal n becomes normalize(n + BumpDepth * G * t), t the component
   * tangent to n of (P - C) / Radius: positive values raise a bump, negative ones
   * press a dent. The Erase blend mode restores the initial normals instead. Values
   * beyond the range are clamped to it (at 1000 the normals lie almost in the tangent
   * plane already; far larger ones overflow the float normals).
   */
  vtkSetClampMacro(BumpDepth, double, -1000.0, 1000.0);
  vtkGetMacro(BumpDepth, double);
  ///@}

  ///@{
  /**
   * Normal-aware painting (default off): skip samples whose normal makes an angle
   * larger than MaxNormalAngle (degrees, 0-180; default 90) with the normal at the
   * dab centre (the normal of the sample closest to the centre, or a per-dab
   * "Normal" array). Limits the colour leakage of the volume brush through thin
   * walls (paper Fig. 5).
   */
  vtkSetMacro(NormalAware, bool);
  vtkGetMacro(NormalAware, bool);
  vtkBooleanMacro(NormalAware, bool);
  vtkSetClampMacro(MaxNormalAngle, double, 0.0, 180.0);
  vtkGetMacro(MaxNormalAngle, double);
  ///@}

  ///@{
  /**
   * Pressure (a per-dab factor in [0, 1], 1 for dabs without one) scales the
   * radius (default off) and/or the strength (default on).
   */
  vtkSetMacro(PressureAffectsRadius, bool);
  vtkGetMacro(PressureAffectsRadius, bool);
  vtkBooleanMacro(PressureAffectsRadius, bool);
  vtkSetMacro(PressureAffectsStrength, bool);
  vtkGetMacro(PressureAffectsStrength, bool);
  vtkBooleanMacro(PressureAffectsStrength, bool);
  ///@}

  /**
   * Modification time including the custom falloff's.
   */
  vtkMTimeType GetMTime() override;

protected:
  vtkOFBBrush();
  ~vtkOFBBrush() override;

  double Radius;
  double Color[4];
  double Strength;
  int Falloff;
  int BlendMode;
  int Target;
  double SmearAmount;
  double BumpDepth;
  bool NormalAware;
  double MaxNormalAngle;
  bool PressureAffectsRadius;
  bool PressureAffectsStrength;
  vtkSmartPointer<vtkPiecewiseFunction> CustomFalloff;

private:
  vtkOFBBrush(const vtkOFBBrush&) = delete;
  void operator=(const vtkOFBBrush&) = delete;
};

#endif
