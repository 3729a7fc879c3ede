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
  : Impl(new Internals)
  , Spacing(0.25)
  , UndoLimit(vtkIdType(256) << 20)
  , MirrorX(false)
  , MirrorY(false)
  , MirrorZ(false)
  , InStroke(false)
{
  this->MirrorOrigin[0] = this->MirrorOrigin[1] = this->MirrorOrigin[2] = 0.0;
  this->DefaultColor[0] = this->DefaultColor[1] = this->DefaultColor[2] = 1.0;
  this->DefaultColor[3] = 1.0;
  this->Impl->Brush = vtkSmartPointer<vtkOFBBrush>::New();
  this->Impl->StrokeDabs = vtkSmartPointer<vtkPoints>::New();
  this->Impl->StrokeDabs->SetDataTypeToDouble();
}

//------------------------------------------------------------------------------
vtkOFBPainter::~vtkOFBPainter() = default;

//------------------------------------------------------------------------------
void vtkOFBPainter::SetOFB(vtkOFB* ofb)
{
  if (this->Impl->OFB == ofb)
  {
    return;
  }
  if (this->InStroke)
  {
    this->EndStroke();
  }
  this->Impl->OFB = ofb;
  this->Impl->Ready = false;
  this->Impl->UndoSteps.clear();
  this->Impl->RedoSteps.clear();
  this->Impl->Open.Clear();
  this->Impl->Kernel.Reset(nullptr, nullptr, nullptr);
  this->Modified();
}

//------------------------------------------------------------------------------
vtkOFB* vtkOFBPainter::GetOFB() const
{
  return this->Impl->OFB;
}

//------------------------------------------------------------------------------
void vtkOFBPainter::SetBrush(vtkOFBBrush* brush)
{
  if (this->Impl->Brush != brush)
  {
    this->Impl->Brush = brush;
    this->Modified();
  }
}

//------------------------------------------------------------------------------
vtkOFBBrush* vtkOFBPainter::GetBrush() const
{
  return this->Impl->Brush;
}

//------------------------------------------------------------------------------
vtkPoints* vtkOFBPainter::GetStrokeDabs() const
{
  return this->Impl->StrokeDabs;
}

//------------------------------------------------------------------------------
bool vtkOFBPainter::Prepare(bool needColors, bool needNormals)
{
  Internals& impl = *this->Impl;
  vtkOFB* ofb = impl.OFB;
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
  vtkDataArray* colorArray = pd->GetArray("Colors");
  auto* colors = vtkUnsignedCharArray::SafeDownCast(colorArray);
  if (colorArray &&
    (!colors || colors->GetNumberOfComponents() != 4 || colors->GetNumberOfTuples() != n))
  {
    vtkErrorMacro("The OFB's \"Colors\" array is not RGBA unsigned char with one tuple per "
                  "sample: cannot paint it.");
    return false;
  }
  vtkDataArray* normalArray = pd->GetArray("Normals");
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
  if (impl.Ready)
  {
    const bool rebuilt = ofb->GetStructureMTime() != impl.LastStructureTime ||
      n != impl.LastNumberOfSamples || (impl.LastColors && colors != impl.LastColors) ||
      (impl.LastNormals && normals != impl.LastNormals);
    if (rebuilt || ofb->GetMTime() != impl.LastMTime)
    {
      if (!impl.UndoSteps.empty() || !impl.RedoSteps.empty() || !impl.Open.Empty())
      {
        vtkWarningMacro("The OFB was changed by something other than this painter since its "
                        "last change: its undo history is dropped.");
      }
      impl.Kernel.ClearRecorded(impl.Open.Colors, impl.Open.Normals);
      impl.UndoSteps.clear();
      impl.RedoSteps.clear();
      impl.Open.Clear();
      if (rebuilt)
      {
        impl.Ready = false;
      }
    }
  }

  if (needColors && !colors)
  {
    // Created on demand, filled with DefaultColor.
    auto created = vtkSmartPointer<vtkUnsignedCharArray>::New();
    created->SetName("Colors");
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

  if (!impl.Ready)
  {
    impl.Kernel.Reset(ofb, colors, normals);
    impl.Ready = true;
  }
  else
  {
    impl.Kernel.SetArrays(colors, normals);
  }
  impl.LastColors = colors;
  impl.LastNormals = normals;
  impl.LastStructureTime = ofb->GetStructureMTime();
  impl.LastNumberOfSamples = n;
  return true;
}

//------------------------------------------------------------------------------
vtkIdType vtkOFBPainter::Finish()
{
  Internals& impl = *this->Impl;
  // A large dab changes hundreds of short runs (rows of cells, interrupted by
  // samples at other depths). vtkOFB keeps its newest 192 marks exact: runs are
  // joined across the smallest gaps first until at most 128 remain, so that one
  // call's marks stay exact and the mapper re-sends few extra samples.
  const vtkIdType count = impl.Kernel.CollectChanged(impl.Ranges, 128);
  for (const auto& r : impl.Ranges)
  {
    impl.OFB->MarkSamplesModified(r.first, r.second);
  }
  if (count > 0)
  {
    impl.OFB->Modified();
  }
  impl.LastMTime = impl.OFB->GetMTime();
  return count;
}

//------------------------------------------------------------------------------
bool vtkOFBPainter::Internals::MakeDab(vtkOFBPainter* self,
  const double center[3],
  double pressure,
  vtkOFBDab& dab) const
{
  vtkOFBBrush* brush = this->Brush;
  if (!Finite3(center))
  {
    vtkErrorWithObjectMacro(self, "A dab centre is not finite (NaN or infinite): nothing painted.");
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
vtkIdType vtkOFBPainter::Internals::Paint(vtkOFBPainter* self, std::vector<vtkOFBDab>& dabs)
{
  vtkOFBBrush* brush = this->Brush;
  if (!brush)
  {
    vtkErrorWithObjectMacro(self, "No brush: call SetBrush with a vtkOFBBrush.");
    return 0;
  }
  for (const vtkOFBDab& d : dabs)
  {
    if (!(d.Radius > 0.0) || !std::isfinite(d.Radius) || !std::isfinite(d.Strength))
    {
      vtkErrorWithObjectMacro(self,
        "Dab radius " << d.Radius << " is not positive and finite, or its strength " << d.Strength
                      << " is not finite: nothing painted.");
      return 0;
    }
  }
  // NaN passes the brush's clamps (and would become a colour byte undefined by C++).
  const double more[3] = {
    brush->GetSmearAmount(), brush->GetBumpDepth(), brush->GetMaxNormalAngle()
  };
  if (!std::all_of(more, more + 3, [](double v) { return std::isfinite(v); }))
  {
    vtkErrorWithObjectMacro(
      self, "The brush's SmearAmount, BumpDepth or MaxNormalAngle is not finite.");
    return 0;
  }
  if (!Finite3(self->MirrorOrigin) && (self->MirrorX || self->MirrorY || self->MirrorZ))
  {
    vtkErrorWithObjectMacro(self, "MirrorOrigin is not finite: nothing painted.");
    return 0;
  }
  this->AddMirrorImages(self, dabs);
  const int target = brush->GetTarget();
  if (!self->Prepare(target != vtkOFBBrush::NormalTarget, target == vtkOFBBrush::NormalTarget))
  {
    return 0;
  }
  vtkOFBPaintSettings settings;
  settings.Falloff = brush->GetFalloff();
  settings.BlendMode = brush->GetBlendMode();
  settings.Target = target;
  settings.SmearAmount = brush->GetSmearAmount();
  settings.BumpDepth = brush->GetBumpDepth();
  settings.NormalAware = brush->GetNormalAware();
  settings.CosMaxAngle = std::cos(vtkMath::RadiansFromDegrees(brush->GetMaxNormalAngle()));
  // Without an undo budget the previous values would be dropped at once: keep none,
  // and drop the older steps, which no longer lead back from what this call paints.
  settings.RecordUndo = self->UndoLimit > 0;
  if (!settings.RecordUndo)
  {
    self->ClearHistory();
  }
  if (settings.Falloff == vtkOFBBrush::Custom && brush->GetCustomFalloff())
  {
    settings.CustomTable.resize(CustomTableSize);
    for (int i = 0; i < CustomTableSize; ++i)
    {
      settings.CustomTable[i] = brush->EvaluateFalloff(i / double(CustomTableSize - 1));
    }
  }
  if (settings.NormalAware && !this->LastNormals)
  {
    vtkWarningWithObjectMacro(
      self, "NormalAware needs a \"Normals\" sample array; painting without it.");
  }

  bool reported = false;
  std::function<void(double)> progress = [self, &reported](double p)
  {
    reported = true;
    self->InvokeEvent(vtkCommand::ProgressEvent, &p);
  };
  this->Kernel.Paint(dabs, settings, this->Open.Colors, this->Open.Normals, progress);
  if (reported)
  {
    double done = 1.0;
    self->InvokeEvent(vtkCommand::ProgressEvent, &done);
  }
  const vtkIdType count = self->Finish();
  if (!self->InStroke)
  {
    self->CloseStep();
  }
  return count;
}

//------------------------------------------------------------------------------
int vtkOFBPainter::GetMirrorReflections(const double point[3],
  double reflections[21],
  int axes[7]) const
{
  const int mirrors = (this->MirrorX ? 1 : 0) | (this->MirrorY ? 2 : 0) | (this->MirrorZ ? 4 : 0);
  int count = 0;
  // Reflection m flips the axes of its bits: x, y, xy, z, xz, yz, xyz.
  for (int m = 1; m < 8; ++m)
  {
    if ((m & mirrors) != m)
    {
      continue;
    }
    double* q = reflections + 3 * count;
    for (int a = 0; a < 3; ++a)
    {
      q[a] = (m & (1 << a)) ? 2.0 * this->MirrorOrigin[a] - point[a] : point[a];
    }
    bool repeated = std::equal(q, q + 3, point);
    for (int k = 0; k < count && !repeated; ++k)
    {
      repeated = std::equal(q, q + 3, reflections + 3 * k);
    }
    if (!repeated)
    {
      axes[count++] = m;
    }
  }
  return count;
}

//------------------------------------------------------------------------------
void vtkOFBPainter::Internals::AddMirrorImages(const vtkOFBPainter* self,
  std::vector<vtkOFBDab>& dabs)
{
  if (!self->MirrorX && !self->MirrorY && !self->MirrorZ)
  {
    return;
  }
  std::vector<vtkOFBDab> all;
  all.reserve(dabs.size() * 8);
  double centres[21];
  int axes[7];
  for (const vtkOFBDab& dab : dabs)
  {
    all.push_back(dab);
    const int count = self->GetMirrorReflections(dab.Center, centres, axes);
    for (int k = 0; k < count; ++k)
    {
      vtkOFBDab image = dab;
      for (int a = 0; a < 3; ++a)
      {
        image.Center[a] = centres[3 * k + a];
        if (axes[k] & (1 << a))
        {
          image.Previous[a] = 2.0 * self->MirrorOrigin[a] - dab.Previous[a];
          image.Normal[a] = -dab.Normal[a];
        }
      }
      all.push_back(image);
    }
  }
  dabs.swap(all);
}

//------------------------------------------------------------------------------
vtkIdType vtkOFBPainter::Dab(const double center[3])
{
  std::vector<vtkOFBDab> dabs(1);
  if (!this->Impl->MakeDab(this, center, 1.0, dabs[0]))
  {
    return 0;
  }
  return this->Impl->Paint(this, dabs);
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
  if (!centers)
  {
    vtkErrorMacro("Dabs: no points given.");
    return 0;
  }
  std::vector<vtkOFBDab> dabs(centers->GetNumberOfPoints());
  for (vtkIdType i = 0; i < centers->GetNumberOfPoints(); ++i)
  {
    double p[3];
    centers->GetPoint(i, p);
    if (!this->Impl->MakeDab(this, p, 1.0, dabs[i]))
    {
      return 0;
    }
  }
  return this->Impl->Paint(this, dabs);
}

//------------------------------------------------------------------------------
vtkIdType vtkOFBPainter::Dabs(vtkPolyData* input)
{
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
  if (!this->Impl->Brush)
  {
    vtkErrorMacro("No brush: call SetBrush with a vtkOFBBrush.");
    return 0;
  }
  const bool strengthByPressure = this->Impl->Brush->GetPressureAffectsStrength();

  const vtkIdType n = input->GetNumberOfPoints();
  std::vector<vtkOFBDab> dabs(n);
  for (vtkIdType i = 0; i < n; ++i)
  {
    double p[3];
    input->GetPoint(i, p);
    const double pr = pressure ? pressure->GetComponent(i, 0) : 1.0;
    vtkOFBDab& d = dabs[i];
    if (!this->Impl->MakeDab(this, p, pr, d))
    {
      return 0;
    }
    if (radius)
    {
      const bool byPressure = this->Impl->Brush->GetPressureAffectsRadius();
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
  return this->Impl->Paint(this, dabs);
}

//------------------------------------------------------------------------------
void vtkOFBPainter::BeginStroke()
{
  if (this->InStroke)
  {
    this->EndStroke();
  }
  this->InStroke = true;
  this->Impl->HasLastPoint = false;
  this->Impl->HasLastDab = false;
  this->Impl->SinceLastDab = 0.0;
  this->Impl->StrokeDabs->Initialize();
}

//------------------------------------------------------------------------------
vtkIdType vtkOFBPainter::StrokeTo(const double p[3], double pressure)
{
  if (!Finite3(p))
  {
    vtkErrorMacro("A stroke point is not finite (NaN or infinite): ignored.");
    return 0;
  }
  if (!this->Impl->Brush)
  {
    vtkErrorMacro("No brush: call SetBrush with a vtkOFBBrush.");
    return 0;
  }
  if (!this->InStroke)
  {
    this->BeginStroke();
  }
  Internals& impl = *this->Impl;
  pressure = std::min(1.0, std::max(0.0, std::isfinite(pressure) ? pressure : 1.0));
  std::vector<vtkOFBDab> dabs;
  auto place = [&](const double c[3], double pr)
  {
    vtkOFBDab d;
    this->Impl->MakeDab(this, c, pr, d);
    d.HasPrevious = impl.HasLastDab;
    std::copy(impl.LastDab, impl.LastDab + 3, d.Previous);
    dabs.push_back(d);
    std::copy(c, c + 3, impl.LastDab);
    impl.HasLastDab = true;
    impl.StrokeDabs->InsertNextPoint(c);
  };
  if (!impl.HasLastPoint)
  {
    place(p, pressure);
    impl.SinceLastDab = 0.0;
  }
  else
  {
    // Dabs every Spacing * radius of path length, the radius at the last dab.
    const glm::dvec3 a(impl.LastPoint[0], impl.LastPoint[1], impl.LastPoint[2]);
    const glm::dvec3 b(p[0], p[1], p[2]);
    const double length = glm::length(b - a);
    vtkOFBBrush* brush = impl.Brush;
    const double cellSize = impl.OFB ? impl.OFB->GetCellSize() : 0.0;
    auto stepAt = [&](double pr)
    {
      const double r = brush->GetRadius() * (brush->GetPressureAffectsRadius() ? pr : 1.0);
      return vtkOFBDabStep(this->Spacing, r, cellSize);
    };
    if (length / stepAt(std::min(pressure, impl.LastPressure)) > vtkOFBMaximumStrokeDabs)
    {
      vtkErrorMacro("StrokeTo: this segment ("
        << length << " long) would place more than " << vtkOFBMaximumStrokeDabs << " dabs (radius "
        << brush->GetRadius() << ", Spacing " << this->Spacing << "): nothing painted.");
      std::copy(p, p + 3, impl.LastPoint);
      impl.LastPressure = pressure;
      impl.SinceLastDab = 0.0;
      return 0;
    }
    double lastPressure = impl.LastPressure;
    double s = stepAt(lastPressure) - impl.SinceLastDab;
    double lastS = -impl.SinceLastDab;
    while (s <= length && length > 0.0)
    {
      const double t = s / length;
      const glm::dvec3 c = a + t * (b - a);
      const double pr = impl.LastPressure + t * (pressure - impl.LastPressure);
      const double cc[3] = { c.x, c.y, c.z };
      place(cc, pr);
      lastS = s;
      lastPressure = pr;
      s += stepAt(pr);
    }
    impl.SinceLastDab = length - lastS;
  }
  std::copy(p, p + 3, impl.LastPoint);
  impl.LastPressure = pressure;
  impl.HasLastPoint = true;
  return dabs.empty() ? 0 : this->Impl->Paint(this, dabs);
}

//------------------------------------------------------------------------------
vtkIdType vtkOFBPainter::StrokeTo(double x, double y, double z, double pressure)
{
  const double p[3] = { x, y, z };
  return this->StrokeTo(p, pressure);
}

//------------------------------------------------------------------------------
void vtkOFBPainter::EndStroke()
{
  if (!this->InStroke)
  {
    return;
  }
  this->InStroke = false;
  this->CloseStep();
}

//------------------------------------------------------------------------------
void vtkOFBPainter::CloseStep()
{
  Internals& impl = *this->Impl;
  if (impl.Open.Empty())
  {
    return;
  }
  impl.Kernel.ClearRecorded(impl.Open.Colors, impl.Open.Normals);
  // A step records each sample once, so the order of its records does not matter to
  // Restore(). Spare capacity beyond a quarter is given back.
  auto trim = [](auto& v)
  {
    if (v.capacity() > v.size() + v.size() / 4)
    {
      v.shrink_to_fit();
    }
  };
  trim(impl.Open.Colors);
  trim(impl.Open.Normals);
  impl.UndoSteps.push_back(std::move(impl.Open));
  impl.Open = vtkofbpainter::Step();
  impl.RedoSteps.clear();
  this->EnforceUndoLimit();
}

//------------------------------------------------------------------------------
void vtkOFBPainter::EnforceUndoLimit()
{
  Internals& impl = *this->Impl;
  vtkIdType bytes = impl.HistoryBytes();
  while (bytes > this->UndoLimit && !impl.RedoSteps.empty())
  {
    bytes -= impl.RedoSteps.back().Bytes(); // the step furthest from now
    impl.RedoSteps.pop_back();
  }
  while (bytes > this->UndoLimit && !impl.UndoSteps.empty())
  {
    bytes -= impl.UndoSteps.front().Bytes(); // the oldest step
    impl.UndoSteps.pop_front();
  }
}

//------------------------------------------------------------------------------
vtkIdType vtkOFBPainter::Restore(bool undo)
{
  if (this->InStroke)
  {
    this->EndStroke();
  }
  Internals& impl = *this->Impl;
  std::deque<vtkofbpainter::Step>& from = undo ? impl.UndoSteps : impl.RedoSteps;
  std::deque<vtkofbpainter::Step>& to = undo ? impl.RedoSteps : impl.UndoSteps;
  if (from.empty() || !impl.OFB)
  {
    return 0;
  }
  // Drops the history if something else changed the OFB meanwhile.
  if (!this->Prepare(false, false) || from.empty())
  {
    return 0;
  }
  vtkofbpainter::Step step = std::move(from.back());
  from.pop_back();
  // Swap each recorded value with the current one: the step becomes its inverse.
  if (!step.Colors.empty())
  {
    unsigned char* colors = impl.LastColors->GetPointer(0);
    for (auto& r : step.Colors)
    {
      unsigned char* c = colors + 4 * static_cast<vtkIdType>(r.Id);
      for (int k = 0; k < 4; ++k)
      {
        std::swap(c[k], r.Value[k]);
      }
      impl.Kernel.MarkChanged(r.Id);
    }
  }
  if (!step.Normals.empty() && impl.LastNormals)
  {
    float* normals = impl.LastNormals->GetPointer(0);
    for (auto& r : step.Normals)
    {
      float* n = normals + 3 * static_cast<vtkIdType>(r.Id);
      for (int k = 0; k < 3; ++k)
      {
        std::swap(n[k], r.Value[k]);
      }
      impl.Kernel.MarkChanged(r.Id);
    }
  }
  to.push_back(std::move(step));
  return this->Finish();
}

//------------------------------------------------------------------------------
vtkIdType vtkOFBPainter::Undo()
{
  return this->Restore(true);
}

//------------------------------------------------------------------------------
vtkIdType vtkOFBPainter::Redo()
{
  return this->Restore(false);
}

//------------------------------------------------------------------------------
bool vtkOFBPainter::CanUndo() const
{
  return !this->Impl->UndoSteps.empty() || !this->Impl->Open.Empty();
}

//------------------------------------------------------------------------------
bool vtkOFBPainter::CanRedo() const
{
  return !this->Impl->RedoSteps.empty();
}

//------------------------------------------------------------------------------
void vtkOFBPainter::ClearHistory()
{
  Internals& impl = *this->Impl;
  if (impl.Ready)
  {
    impl.Kernel.ClearRecorded(impl.Open.Colors, impl.Open.Normals);
  }
  impl.Open.Clear();
  impl.UndoSteps.clear();
  impl.RedoSteps.clear();
}

//------------------------------------------------------------------------------
int vtkOFBPainter::GetNumberOfUndoSteps() const
{
  return static_cast<int>(this->Impl->UndoSteps.size()) + (this->Impl->Open.Empty() ? 0 : 1);
}

//------------------------------------------------------------------------------
int vtkOFBPainter::GetNumberOfRedoSteps() const
{
  return static_cast<int>(this->Impl->RedoSteps.size());
}

//------------------------------------------------------------------------------
vtkIdType vtkOFBPainter::GetUndoMemory() const
{
  return this->Impl->HistoryBytes();
}

//------------------------------------------------------------------------------
void vtkOFBPainter::ResetInitialValues()
{
  this->Impl->Kernel.ResetInitialValues();
}

//------------------------------------------------------------------------------
vtkIdType vtkOFBPainter::GetScratchMemory() const
{
  return this->Impl->Kernel.GetMemory();
}

//------------------------------------------------------------------------------
void vtkOFBPainter::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "OFB: " << this->Impl->OFB.GetPointer() << "\n";
  os << indent << "Brush: " << this->Impl->Brush.GetPointer() << "\n";
  os << indent << "Spacing: " << this->Spacing << "\n";
  os << indent << "DefaultColor: (" << this->DefaultColor[0] << ", " << this->DefaultColor[1]
     << ", " << this->DefaultColor[2] << ", " << this->DefaultColor[3] << ")\n";
  os << indent << "UndoLimit: " << this->UndoLimit << "\n";
  os << indent << "MirrorX: " << this->MirrorX << ", MirrorY: " << this->MirrorY
     << ", MirrorZ: " << this->MirrorZ << "\n";
  os << indent << "MirrorOrigin: (" << this->MirrorOrigin[0] << ", " << this->MirrorOrigin[1]
     << ", " << this->MirrorOrigin[2] << ")\n";
  os << indent << "InStroke: " << (this->InStroke ? "yes" : "no") << "\n";
  os << indent << "UndoSteps: " << this->GetNumberOfUndoSteps() << "\n";
  os << indent << "RedoSteps: " << this->GetNumberOfRedoSteps() << "\n";
  os << indent << "UndoMemory: " << this->GetUndoMemory() << "\n";
}
