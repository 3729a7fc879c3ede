#include "vtkOFBPainter.h"

#include "vtkCommand.h"
#include "vtkDataArray.h"
#include "vtkFloatArray.h"
#include "vtkMath.h"
#include "vtkOFB.h"
#include "vtkOFBBrush.h"
#include "vtkOFBDabArrays.h"
#include "vtkOFBHugePages.h"
#include "vtkOFBPaintKernel.h"
#include "vtkOFBPainterInternals.h"
#include "vtkObjectFactory.h"
#include "vtkPiecewiseFunction.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkUnsignedCharArray.h"

#include <glm/glm.hpp>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <deque>

vtkStandardNewMacro(vtkOFBPainter);

namespace
{
// Samples of the Custom falloff's table.
constexpr int CustomTableSize = 4097;

bool Finite3(const double p[3])
{
  return std::isfinite(p[0]) && std::isfinite(p[1]) && std::isfinite(p[2]);
}
}

//------------------------------------------------------------------------------
vtkOFBPainter::vtkOFBPainter()
  : Internals(new vtkInternals)
  , Spacing(0.25)
  , UndoLimit(vtkIdType(256) << 20)
  , MirrorX(false)
  , MirrorY(false)
  , MirrorZ(false)
  , InStroke(false)
  , MaximumDabsPerCall(vtkIdType(1) << 22)
  , AbortPaint(false)
  , FollowSurface(true)
{
  this->MirrorOrigin[0] = this->MirrorOrigin[1] = this->MirrorOrigin[2] = 0.0;
  this->DefaultColor[0] = this->DefaultColor[1] = this->DefaultColor[2] = 1.0;
  this->DefaultColor[3] = 1.0;
  this->Internals->Brush = vtkSmartPointer<vtkOFBBrush>::New();
  this->Internals->StrokeDabs = vtkSmartPointer<vtkPoints>::New();
  this->Internals->StrokeDabs->SetDataTypeToDouble();
}

//------------------------------------------------------------------------------
vtkOFBPainter::~vtkOFBPainter() = default;

//------------------------------------------------------------------------------
vtkOFBPainter::CallScope::CallScope(vtkOFBPainter* painter, const char* what)
  : Painter(painter)
{
  vtkInternals& internals = *painter->Internals;
  if (internals.InCall.exchange(true))
  {
    vtkErrorWithObjectMacro(painter,
      << what
      << ": called while a call of this painter is in progress (from one of its "
         "progress observers, or from another thread): refused, nothing changed.");
    return;
  }
  vtkOFB* ofb = internals.OFB;
  if (ofb && !ofb->BeginExclusiveWrite(painter))
  {
    internals.InCall = false;
    vtkErrorWithObjectMacro(painter,
      << what
      << ": the OFB is being painted by another painter (paint one OFB from one "
         "painter at a time): refused, nothing changed.");
    return;
  }
  internals.HeldOFB = ofb;
  internals.HeldBrush = internals.Brush;
  painter->AbortPaint = false;
  this->Entered = true;
}

//------------------------------------------------------------------------------
vtkOFBPainter::CallScope::~CallScope()
{
  if (!this->Entered)
  {
    return;
  }
  vtkInternals& internals = *this->Painter->Internals;
  if (internals.HeldOFB)
  {
    internals.HeldOFB->EndExclusiveWrite(this->Painter);
  }
  internals.HeldColors = nullptr;
  internals.HeldNormals = nullptr;
  internals.HeldBrush = nullptr;
  internals.HeldOFB = nullptr;
  internals.InCall = false;
}

//------------------------------------------------------------------------------
bool vtkOFBPainter::IsPainting() const
{
  return this->Internals->InCall.load();
}

//------------------------------------------------------------------------------
bool vtkOFBPainter::CheckBrush(const char* what)
{
  if (!this->Internals->Brush)
  {
    vtkErrorMacro(<< what << ": no brush: call SetBrush with a vtkOFBBrush. Nothing painted.");
    return false;
  }
  return true;
}

//------------------------------------------------------------------------------
bool vtkOFBPainter::CheckDabCount(vtkIdType count, const char* what)
{
  if (count > this->MaximumDabsPerCall)
  {
    vtkErrorMacro(<< what << ": " << count << " dabs (mirror reflections included) exceed "
                  << "MaximumDabsPerCall (" << this->MaximumDabsPerCall
                  << "): nothing painted. Paint them in several calls, or raise the limit.");
    return false;
  }
  return true;
}

//------------------------------------------------------------------------------
void vtkOFBPainter::SetOFB(vtkOFB* ofb)
{
  if (this->Internals->OFB == ofb)
  {
    return;
  }
  if (this->Internals->InCall)
  {
    // The call in progress reads the OFB's arrays through raw pointers.
    vtkErrorMacro("SetOFB: called while a painting call is in progress (from one of its "
                  "progress observers?): refused, the OFB is unchanged.");
    return;
  }
  if (this->InStroke)
  {
    this->FinishStroke();
  }
  this->Internals->OFB = ofb;
  this->Internals->Ready = false;
  this->Internals->UndoSteps.clear();
  this->Internals->RedoSteps.clear();
  this->Internals->Open.Clear();
  this->Internals->Kernel.Reset(nullptr, nullptr, nullptr);
  this->Modified();
}

//------------------------------------------------------------------------------
vtkOFB* vtkOFBPainter::GetOFB() const
{
  return this->Internals->OFB;
}

//------------------------------------------------------------------------------
void vtkOFBPainter::SetBrush(vtkOFBBrush* brush)
{
  if (this->Internals->Brush != brush)
  {
    this->Internals->Brush = brush;
    this->Modified();
  }
}

//------------------------------------------------------------------------------
vtkOFBBrush* vtkOFBPainter::GetBrush() const
{
  return this->Internals->Brush;
}

//------------------------------------------------------------------------------
vtkPoints* vtkOFBPainter::GetStrokeDabs() const
{
  return this->Internals->StrokeDabs;
}

//------------------------------------------------------------------------------
bool vtkOFBPainter::Prepare(bool needColors, bool needNormals)
{
  vtkInternals& internals = *this->Internals;
  vtkOFB* ofb = internals.OFB;
  if (!ofb)
  {
    vtkErrorMacro("No OFB to paint: call SetOFB first.");
    return false;
  }
  const vtkIdType n = ofb->GetNumberOfSamples();
  if (n == 0)
  {
    vtkErrorMacro("The OFB has no samples: nothing to paint.");
    return false;
  }
  vtkPointData* pd = ofb->GetSampleData();
  vtkDataArray* colorArray = pd->GetArray(vtkOFB::ColorsArrayName());
  auto* colors = vtkUnsignedCharArray::SafeDownCast(colorArray);
  if (colorArray &&
    (!colors || colors->GetNumberOfComponents() != 4 || colors->GetNumberOfTuples() != n))
  {
    vtkErrorMacro("The OFB's \"Colors\" array is not RGBA unsigned char with one tuple per "
                  "sample: cannot paint it.");
    return false;
  }
  vtkDataArray* normalArray = pd->GetArray(vtkOFB::NormalsArrayName());
  auto* normals = vtkFloatArray::SafeDownCast(normalArray);
  if (normals && (normals->GetNumberOfComponents() != 3 || normals->GetNumberOfTuples() != n))
  {
    normals = nullptr;
  }
  if (needNormals && !normals)
  {
    vtkErrorMacro("Normal painting needs a float \"Normals\" sample array with 3 components; "
                  "the OFB has none.");
    return false;
  }

  // Something else changed the OFB since this painter's last change: the
  // history no longer describes it.
  if (internals.Ready)
  {
    const bool rebuilt = ofb->GetStructureMTime() != internals.LastStructureTime ||
      n != internals.LastNumberOfSamples ||
      // An array freed since reads as null through its weak pointer: changed as well.
      (internals.HadColors && (!internals.LastColors || colors != internals.LastColors)) ||
      (internals.HadNormals && (!internals.LastNormals || normals != internals.LastNormals));
    if (rebuilt || ofb->GetMTime() != internals.LastMTime)
    {
      if (!internals.UndoSteps.empty() || !internals.RedoSteps.empty() || !internals.Open.Empty())
      {
        vtkWarningMacro("The OFB was changed by something other than this painter since its "
                        "last change: its undo history is dropped.");
      }
      internals.Kernel.ClearRecorded(internals.Open.Colors, internals.Open.Normals);
      internals.UndoSteps.clear();
      internals.RedoSteps.clear();
      internals.Open.Clear();
      if (rebuilt)
      {
        internals.Ready = false;
      }
    }
  }

  if (needColors && !colors)
  {
    // Created on demand, filled with DefaultColor.
    auto created = vtkSmartPointer<vtkUnsignedCharArray>::New();
    created->SetName(vtkOFB::ColorsArrayName());
    created->SetNumberOfComponents(4);
    created->SetNumberOfTuples(n);
    vtkofb::AdviseHugePages(created); // dabs land far apart: fewer TLB misses
    unsigned char c[4];
    for (int k = 0; k < 4; ++k)
    {
      c[k] = static_cast<unsigned char>(
        std::min(1.0, std::max(0.0, this->DefaultColor[k])) * 255.0 + 0.5);
    }
    unsigned char* p = created->GetPointer(0);
    for (vtkIdType i = 0; i < n; ++i)
    {
      std::memcpy(p + 4 * i, c, 4);
    }
    pd->SetScalars(created);
    colors = created;
  }

  if (!internals.Ready)
  {
    internals.Kernel.Reset(ofb, colors, normals);
    internals.Ready = true;
  }
  else
  {
    internals.Kernel.SetArrays(colors, normals);
  }
  internals.LastColors = colors;
  internals.LastNormals = normals;
  internals.HadColors = colors != nullptr;
  internals.HadNormals = normals != nullptr;
  // Held until the call returns: an observer that removes them from the OFB does not
  // free them under the kernel.
  internals.HeldColors = colors;
  internals.HeldNormals = normals;
  internals.LastStructureTime = ofb->GetStructureMTime();
  internals.LastNumberOfSamples = n;
  return true;
}

//------------------------------------------------------------------------------
vtkIdType vtkOFBPainter::Finish()
{
  vtkInternals& internals = *this->Internals;
  // A large dab changes hundreds of short runs (rows of cells, interrupted by
  // samples at other depths). vtkOFB keeps its newest 192 marks exact: runs are
  // joined across the smallest gaps first until at most 128 remain, so that one
  // call's marks stay exact and the mapper re-sends few extra samples.
  const vtkIdType count = internals.Kernel.CollectChanged(internals.Ranges, 128);
  for (const auto& r : internals.Ranges)
  {
    internals.OFB->MarkSamplesModified(r.first, r.second);
  }
  if (count > 0)
  {
    internals.OFB->Modified();
  }
  internals.LastMTime = internals.OFB->GetMTime();
  return count;
}

//------------------------------------------------------------------------------
bool vtkOFBPainter::MakeDab(const double center[3], double pressure, vtkOFBDab& dab)
{
  vtkOFBBrush* brush = this->Internals->Brush; // checked by the caller (CheckBrush)
  if (!Finite3(center))
  {
    vtkErrorMacro("A dab centre is not finite (NaN or infinite): nothing painted.");
    return false;
  }
  pressure = std::min(1.0, std::max(0.0, std::isfinite(pressure) ? pressure : 1.0));
  dab.Radius = brush->GetRadius() * (brush->GetPressureAffectsRadius() ? pressure : 1.0);
  dab.Strength = brush->GetStrength() * (brush->GetPressureAffectsStrength() ? pressure : 1.0);
  for (int k = 0; k < 3; ++k)
  {
    dab.Center[k] = center[k];
    dab.Previous[k] = center[k];
    dab.Normal[k] = 0.0;
  }
  const double* c = brush->GetColor();
  for (int k = 0; k < 4; ++k)
  {
    dab.Color[k] = static_cast<float>(std::min(1.0, std::max(0.0, c[k])));
  }
  dab.HasPrevious = false;
  dab.HasNormal = false;
  return true;
}

//------------------------------------------------------------------------------
vtkIdType vtkOFBPainter::Paint(std::vector<vtkOFBDab>& dabs)
{
  vtkOFBBrush* brush = this->Internals->Brush;
  if (!brush)
  {
    vtkErrorMacro("No brush: call SetBrush with a vtkOFBBrush.");
    return 0;
  }
  for (const vtkOFBDab& d : dabs)
  {
    if (!(d.Radius > 0.0) || !std::isfinite(d.Radius) || !std::isfinite(d.Strength))
    {
      vtkErrorMacro("Dab radius " << d.Radius << " is not positive and finite, or its strength "
                                  << d.Strength << " is not finite: nothing painted.");
      return 0;
    }
  }
  // NaN passes the brush's clamps (and would become a colour byte undefined by C++).
  const double more[3] = {
    brush->GetSmearAmount(), brush->GetBumpDepth(), brush->GetMaxNormalAngle()
  };
  if (!std::all_of(more, more + 3, [](double v) { return std::isfinite(v); }))
  {
    vtkErrorMacro("The brush's SmearAmount, BumpDepth or MaxNormalAngle is not finite.");
    return 0;
  }
  // The brush's setters refuse other values; a subclass of the brush could still hold one.
  const int falloff = brush->GetFalloff();
  const int blendMode = brush->GetBlendMode();
  const int target = brush->GetTarget();
  if (falloff < 0 || falloff >= vtkOFBBrush::NUMBER_OF_FALLOFFS || blendMode < 0 ||
    blendMode >= vtkOFBBrush::NUMBER_OF_BLEND_MODES || target < 0 ||
    target >= vtkOFBBrush::NUMBER_OF_TARGETS)
  {
    vtkErrorMacro("The brush's Falloff (" << falloff << "), BlendMode (" << blendMode
                                          << ") or Target (" << target
                                          << ") is not one of its enumerators: nothing painted.");
    return 0;
  }
  const bool mirrored = this->MirrorX || this->MirrorY || this->MirrorZ;
  if (!Finite3(this->MirrorOrigin) && mirrored)
  {
    vtkErrorMacro("MirrorOrigin is not finite: nothing painted.");
    return 0;
  }
  // Counted after reflection, before the reflections are stored.
  vtkIdType total = static_cast<vtkIdType>(dabs.size());
  if (mirrored && total <= this->MaximumDabsPerCall)
  {
    double reflections[21];
    int axes[7];
    for (const vtkOFBDab& d : dabs)
    {
      total += this->GetMirrorReflections(d.Center, reflections, axes);
    }
  }
  if (!this->CheckDabCount(total, "Paint"))
  {
    return 0;
  }
  this->AddMirrorImages(dabs);
  if (!this->Prepare(target != vtkOFBBrush::TARGET_NORMAL, target == vtkOFBBrush::TARGET_NORMAL))
  {
    return 0;
  }
  vtkOFBPaintSettings settings;
  settings.Falloff = static_cast<vtkOFBBrush::FalloffType>(falloff);
  settings.BlendMode = static_cast<vtkOFBBrush::BlendModeType>(blendMode);
  settings.Target = static_cast<vtkOFBBrush::TargetType>(target);
  settings.SmearAmount = brush->GetSmearAmount();
  // As the brush clamps it (a subclass of the brush could hold more): a larger depth
  // overflows the float normals.
  settings.BumpDepth = std::min(1000.0, std::max(-1000.0, brush->GetBumpDepth()));
  settings.NormalAware = brush->GetNormalAware();
  settings.CosMaxAngle = std::cos(vtkMath::RadiansFromDegrees(brush->GetMaxNormalAngle()));
  // Without an undo budget the previous values would be dropped at once: keep none,
  // and drop the older steps, which no longer lead back from what this call paints.
  settings.RecordUndo = this->UndoLimit > 0;
  if (!settings.RecordUndo)
  {
    this->DropHistory();
  }
  if (settings.Falloff == vtkOFBBrush::FALLOFF_CUSTOM && brush->GetCustomFalloff())
  {
    settings.CustomTable.resize(CustomTableSize);
    for (int i = 0; i < CustomTableSize; ++i)
    {
      settings.CustomTable[i] = brush->EvaluateFalloff(i / double(CustomTableSize - 1));
    }
  }
  if (settings.NormalAware && !this->Internals->LastNormals)
  {
    vtkWarningMacro("NormalAware needs a \"Normals\" sample array; painting without it.");
  }

  bool reported = false;
  // The observer may set AbortPaint: the kernel stops before its next dab.
  std::function<bool(double)> progress = [this, &reported](double p)
  {
    reported = true;
    this->InvokeEvent(vtkCommand::ProgressEvent, &p);
    return !this->AbortPaint;
  };
  this->Internals->Kernel.Paint(
    dabs, settings, this->Internals->Open.Colors, this->Internals->Open.Normals, progress);
  if (reported)
  {
    double done = 1.0;
    this->InvokeEvent(vtkCommand::ProgressEvent, &done);
  }
  const vtkIdType count = this->Finish();
  if (!this->InStroke)
  {
    this->CloseStep();
  }
  return count;
}

//------------------------------------------------------------------------------
void vtkOFBPainter::CopySettings(vtkOFBPainter* source)
{
  if (!source || source == this)
  {
    return;
  }
  this->SetSpacing(source->Spacing);
  this->SetMirrorX(source->MirrorX);
  this->SetMirrorY(source->MirrorY);
  this->SetMirrorZ(source->MirrorZ);
  this->SetMirrorOrigin(source->MirrorOrigin);
  this->SetDefaultColor(source->DefaultColor);
  this->SetUndoLimit(source->UndoLimit);
  this->SetMaximumDabsPerCall(source->MaximumDabsPerCall);
  this->SetFollowSurface(source->FollowSurface);
}

//------------------------------------------------------------------------------
vtkIdType vtkOFBPainter::Dab(const double center[3])
{
  CallScope scope(this, "Dab");
  if (!scope || !this->CheckBrush("Dab"))
  {
    return 0;
  }
  std::vector<vtkOFBDab> dabs(1);
  if (!this->MakeDab(center, 1.0, dabs[0]))
  {
    return 0;
  }
  return this->Paint(dabs);
}

//------------------------------------------------------------------------------
vtkIdType vtkOFBPainter::Dab(double x, double y, double z)
{
  const double c[3] = { x, y, z };
  return this->Dab(c);
}

//------------------------------------------------------------------------------
vtkIdType vtkOFBPainter::Dabs(vtkPoints* centers)
{
  CallScope scope(this, "Dabs");
  if (!scope)
  {
    return 0;
  }
  if (!centers)
  {
    vtkErrorMacro("Dabs: no points given.");
    return 0;
  }
  if (!this->CheckBrush("Dabs") || !this->CheckDabCount(centers->GetNumberOfPoints(), "Dabs"))
  {
    return 0;
  }
  std::vector<vtkOFBDab> dabs(centers->GetNumberOfPoints());
  for (vtkIdType i = 0; i < centers->GetNumberOfPoints(); ++i)
  {
    double p[3];
    centers->GetPoint(i, p);
    if (!this->MakeDab(p, 1.0, dabs[i]))
    {
      return 0;
    }
  }
  return this->Paint(dabs);
}

//------------------------------------------------------------------------------
vtkIdType vtkOFBPainter::Dabs(vtkPolyData* input)
{
  CallScope scope(this, "Dabs");
  if (!scope)
  {
    return 0;
  }
  if (!input || !input->GetPoints())
  {
    vtkErrorMacro("Dabs: no points given.");
    return 0;
  }
  vtkOFBDabArrays arrays{ input, std::string() };
  vtkDataArray* radius = arrays.Get("Radius", 1);
  vtkDataArray* color = arrays.Get("Color", 3);
  vtkDataArray* strength = arrays.Get("Strength", 1);
  vtkDataArray* pressure = arrays.Get("Pressure", 1);
  vtkDataArray* previous = arrays.Get("PreviousPosition", 3);
  vtkDataArray* normal = arrays.Get("Normal", 3);
  if (!arrays.Error.empty())
  {
    vtkErrorMacro("Dabs: " << arrays.Error << " Nothing painted.");
    return 0;
  }
  const double colorScale = color && color->GetDataType() == VTK_UNSIGNED_CHAR ? 1.0 / 255.0 : 1.0;
  if (!this->CheckBrush("Dabs") || !this->CheckDabCount(input->GetNumberOfPoints(), "Dabs"))
  {
    return 0;
  }
  const bool strengthByPressure = this->Internals->Brush->GetPressureAffectsStrength();

  const vtkIdType n = input->GetNumberOfPoints();
  std::vector<vtkOFBDab> dabs(n);
  for (vtkIdType i = 0; i < n; ++i)
  {
    double p[3];
    input->GetPoint(i, p);
    const double pr = pressure ? pressure->GetComponent(i, 0) : 1.0;
    vtkOFBDab& d = dabs[i];
    if (!this->MakeDab(p, pr, d))
    {
      return 0;
    }
    if (radius)
    {
      const bool byPressure = this->Internals->Brush->GetPressureAffectsRadius();
      const double prc = std::min(1.0, std::max(0.0, pr));
      d.Radius = radius->GetComponent(i, 0) * (byPressure ? prc : 1.0);
    }
    if (strength)
    {
      const double prc = std::min(1.0, std::max(0.0, pr));
      d.Strength = std::min(1.0, std::max(0.0, strength->GetComponent(i, 0))) *
        (strengthByPressure ? prc : 1.0);
    }
    if (color)
    {
      for (int k = 0; k < 4; ++k)
      {
        const double v =
          k < color->GetNumberOfComponents() ? color->GetComponent(i, k) * colorScale : 1.0;
        d.Color[k] = static_cast<float>(std::min(1.0, std::max(0.0, v)));
      }
    }
    if (previous)
    {
      previous->GetTuple(i, d.Previous);
      d.HasPrevious = Finite3(d.Previous);
    }
    if (normal)
    {
      normal->GetTuple(i, d.Normal);
      d.HasNormal = Finite3(d.Normal);
    }
  }
  return this->Paint(dabs);
}

//------------------------------------------------------------------------------
vtkIdType vtkOFBPainter::GetScratchMemory() const
{
  return this->Internals->Kernel.GetMemory();
}

//------------------------------------------------------------------------------
void vtkOFBPainter::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "OFB: " << this->Internals->OFB.GetPointer() << "\n";
  os << indent << "Brush: " << this->Internals->Brush.GetPointer() << "\n";
  os << indent << "Spacing: " << this->Spacing << "\n";
  os << indent << "DefaultColor: (" << this->DefaultColor[0] << ", " << this->DefaultColor[1]
     << ", " << this->DefaultColor[2] << ", " << this->DefaultColor[3] << ")\n";
  os << indent << "UndoLimit: " << this->UndoLimit << "\n";
  os << indent << "MaximumDabsPerCall: " << this->MaximumDabsPerCall << "\n";
  os << indent << "AbortPaint: " << this->AbortPaint << "\n";
  os << indent << "FollowSurface: " << this->FollowSurface << "\n";
  os << indent << "MirrorX: " << this->MirrorX << ", MirrorY: " << this->MirrorY
     << ", MirrorZ: " << this->MirrorZ << "\n";
  os << indent << "MirrorOrigin: (" << this->MirrorOrigin[0] << ", " << this->MirrorOrigin[1]
     << ", " << this->MirrorOrigin[2] << ")\n";
  os << indent << "InStroke: " << (this->InStroke ? "yes" : "no") << "\n";
  os << indent << "UndoSteps: " << this->GetNumberOfUndoSteps() << "\n";
  os << indent << "RedoSteps: " << this->GetNumberOfRedoSteps() << "\n";
  os << indent << "UndoMemory: " << this->GetUndoMemory() << "\n";
}
