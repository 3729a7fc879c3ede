#include "vtkOFBPaintFilter.h"

#include "vtkCallbackCommand.h"
#include "vtkCellArray.h"
#include "vtkDataArray.h"
#include "vtkDoubleArray.h"
#include "vtkFloatArray.h"
#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkMath.h"
#include "vtkNew.h"
#include "vtkOFB.h"
#include "vtkOFBBrush.h"
#include "vtkOFBDabArrays.h"
#include "vtkOFBInputChecks.h"
#include "vtkOFBPainter.h"
#include "vtkOFBStrokeExchange.h"
#include "vtkOFBStrokePath.h"
#include "vtkOFBStrokeSampler.h"
#include "vtkObjectFactory.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"

#include <glm/glm.hpp>

#include <algorithm>
#include <cmath>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

vtkStandardNewMacro(vtkOFBPaintFilter);

namespace
{
/// The per-point values of the strokes, with the brush's where an array is absent.
struct StrokeValues
{
  vtkPolyData* Strokes;
  vtkOFBBrush* Brush;
  vtkDataArray* Radius;
  vtkDataArray* Color;
  vtkDataArray* Strength;
  vtkDataArray* Pressure;
  double ColorScale;

  double RadiusAt(vtkIdType i) const
  {
    return this->Radius ? this->Radius->GetComponent(i, 0) : this->Brush->GetRadius();
  }
  double PressureAt(vtkIdType i) const
  {
    return this->Pressure ? std::min(1.0, std::max(0.0, this->Pressure->GetComponent(i, 0))) : 1.0;
  }
  void ColorAt(vtkIdType i, double c[4]) const
  {
    for (int k = 0; k < 4; ++k)
    {
      c[k] = k < this->Color->GetNumberOfComponents()
        ? this->Color->GetComponent(i, k) * this->ColorScale
        : 1.0;
    }
  }
};

/// The output arrays of the dabs.
struct DabArrays
{
  vtkNew<vtkPoints> Points;
  vtkNew<vtkDoubleArray> Radius;
  vtkNew<vtkDoubleArray> Pressure;
  vtkNew<vtkDoubleArray> Strength;
  vtkNew<vtkFloatArray> Color;
  vtkNew<vtkDoubleArray> Previous;

  DabArrays()
  {
    this->Points->SetDataTypeToDouble();
    this->Radius->SetName("Radius");
    this->Pressure->SetName("Pressure");
    this->Strength->SetName("Strength");
    this->Color->SetName("Color");
    this->Color->SetNumberOfComponents(4);
    this->Previous->SetName("PreviousPosition");
    this->Previous->SetNumberOfComponents(3);
  }

  /// A dab at `p`, with the values at `t` between points a and b of the strokes.
  void Add(const StrokeValues& v,
    vtkIdType a,
    vtkIdType b,
    double t,
    const double p[3],
    const double previous[3])
  {
    this->Points->InsertNextPoint(p);
    this->Radius->InsertNextValue(v.RadiusAt(a) + t * (v.RadiusAt(b) - v.RadiusAt(a)));
    this->Pressure->InsertNextValue(v.PressureAt(a) + t * (v.PressureAt(b) - v.PressureAt(a)));
    if (v.Strength)
    {
      const double sa = v.Strength->GetComponent(a, 0), sb = v.Strength->GetComponent(b, 0);
      this->Strength->InsertNextValue(sa + t * (sb - sa));
    }
    if (v.Color)
    {
      double ca[4], cb[4];
      v.ColorAt(a, ca);
      v.ColorAt(b, cb);
      float c[4];
      for (int k = 0; k < 4; ++k)
      {
        c[k] = static_cast<float>(ca[k] + t * (cb[k] - ca[k]));
      }
      this->Color->InsertNextTypedTuple(c);
    }
    this->Previous->InsertNextTuple(previous);
  }
};

/// The segments of the strokes' polylines, in order: pairs of point ids.
std::vector<std::pair<vtkIdType, vtkIdType>> Segments(vtkPolyData* strokes)
{
  std::vector<std::pair<vtkIdType, vtkIdType>> segments;
  const vtkIdType* ids = nullptr;
  vtkIdType n = 0;
  vtkCellArray* lines = strokes->GetLines();
  for (lines->InitTraversal(); lines->GetNextCell(n, ids);)
  {
    for (vtkIdType k = 1; k < n; ++k)
    {
      segments.emplace_back(ids[k - 1], ids[k]);
    }
  }
  return segments;
}

/// An empty string when every stroke point is finite with a positive, finite radius.
std::string CheckPoints(vtkPolyData* strokes, const StrokeValues& v)
{
  std::ostringstream error;
  for (vtkIdType i = 0; i < strokes->GetNumberOfPoints(); ++i)
  {
    double p[3];
    strokes->GetPoint(i, p);
    const double r = v.RadiusAt(i);
    if (!std::isfinite(p[0]) || !std::isfinite(p[1]) || !std::isfinite(p[2]))
    {
      error << "Stroke point " << i << " is not finite (NaN or infinite).";
      break;
    }
    if (!(r > 0.0) || !std::isfinite(r))
    {
      error << "Stroke point " << i << " has radius " << r << ", not positive and finite.";
      break;
    }
  }
  return error.str();
}

/**
 * The stroke points on the surface (`at`) and the path of every segment (`paths`): with
 * `followSurface`, every point moves onto the closest sample and each segment becomes a
 * path over the surface; otherwise the points and chords. With `exchange`, `ofb` is this
 * process's piece and the points and paths are those of every process's owned samples.
 */
void PlaceOnSurface(vtkPolyData* strokes,
  const std::vector<std::pair<vtkIdType, vtkIdType>>& segments,
  vtkOFB* ofb,
  bool followSurface,
  vtkOFBStrokeExchange* exchange,
  std::vector<glm::dvec3>& at,
  std::vector<std::vector<glm::dvec3>>& paths)
{
  const vtkIdType numberOfPoints = strokes->GetNumberOfPoints();
  std::vector<glm::dvec3> points(numberOfPoints);
  for (vtkIdType i = 0; i < numberOfPoints; ++i)
  {
    double p[3];
    strokes->GetPoint(i, p);
    points[i] = glm::dvec3(p[0], p[1], p[2]);
  }
  if (followSurface && exchange)
  {
    vtkOFBStrokePath surface(ofb, true);
    surface.PlaceDistributed(points, segments, exchange, at, paths);
    return;
  }
  const vtkOFBStrokePath surface(followSurface ? ofb : nullptr);
  at.resize(numberOfPoints);
  std::vector<vtkIdType> sampleOf(numberOfPoints, -1);
  for (vtkIdType i = 0; i < numberOfPoints; ++i)
  {
    const double p[3] = { points[i].x, points[i].y, points[i].z };
    double q[3];
    sampleOf[i] = surface.IsValid() ? surface.Snap(p, q) : -1;
    at[i] = sampleOf[i] >= 0 ? glm::dvec3(q[0], q[1], q[2]) : points[i];
  }
  paths.assign(segments.size(), std::vector<glm::dvec3>());
  for (size_t k = 0; k < segments.size(); ++k)
  {
    const vtkIdType a = segments[k].first, b = segments[k].second;
    if (sampleOf[a] >= 0 && sampleOf[b] >= 0)
    {
      surface.Trace(sampleOf[a], sampleOf[b], paths[k]);
    }
    else
    {
      paths[k] = { at[a], at[b] };
    }
  }
}

/// The spacing of the dabs and how their radius is read.
struct DabSpacing
{
  double Spacing;
  double CellSize;
  bool ByPressure; // the radius is scaled by the pressure

  double RadiusAt(const StrokeValues& v, vtkIdType i) const
  {
    return v.RadiusAt(i) * (this->ByPressure ? v.PressureAt(i) : 1.0);
  }
};

/// The dabs the strokes will place, at most (each segment at its smaller radius).
double MostDabs(const StrokeValues& v,
  const DabSpacing& s,
  const std::vector<std::pair<vtkIdType, vtkIdType>>& segments,
  const std::vector<std::vector<glm::dvec3>>& paths)
{
  double expected = 0.0;
  for (size_t k = 0; k < segments.size(); ++k)
  {
    expected +=
      vtkOFBStrokeSampler::MostDabs(vtkOFBStrokePath::Length(paths[k], 0, paths[k].size() - 1),
        s.Spacing,
        std::min(s.RadiusAt(v, segments[k].first), s.RadiusAt(v, segments[k].second)),
        s.CellSize);
  }
  return expected;
}

/**
 * The dabs: one per vertex cell's point, then along each polyline the first dab at its
 * first point and the painter's walk along each path, the values interpolated by the
 * length walked.
 */
void PlaceDabs(vtkPolyData* strokes,
  const StrokeValues& v,
  const DabSpacing& s,
  const std::vector<glm::dvec3>& at,
  const std::vector<std::vector<glm::dvec3>>& paths,
  DabArrays& out)
{
  const double none[3] = { std::nan(""), std::nan(""), std::nan("") };
  const vtkIdType* ids = nullptr;
  vtkIdType n = 0;
  vtkCellArray* verts = strokes->GetVerts();
  for (verts->InitTraversal(); verts->GetNextCell(n, ids);)
  {
    for (vtkIdType k = 0; k < n; ++k)
    {
      const glm::dvec3& c = at[ids[k]];
      const double cc[3] = { c.x, c.y, c.z };
      out.Add(v, ids[k], ids[k], 0.0, cc, none);
    }
  }
  size_t segment = 0;
  vtkCellArray* lines = strokes->GetLines();
  for (lines->InitTraversal(); lines->GetNextCell(n, ids);)
  {
    if (n == 0)
    {
      continue;
    }
    double last[3] = { at[ids[0]].x, at[ids[0]].y, at[ids[0]].z };
    out.Add(v, ids[0], ids[0], 0.0, last, none);
    vtkOFBStrokeSampler sampler;
    sampler.Start(s.RadiusAt(v, ids[0]));
    for (vtkIdType k = 1; k < n; ++k, ++segment)
    {
      const std::vector<glm::dvec3>& path = paths[segment];
      std::vector<double> walked(path.size(), 0.0);
      for (size_t i = 1; i < path.size(); ++i)
      {
        walked[i] = walked[i - 1] + glm::length(path[i] - path[i - 1]);
      }
      const double length = walked.back();
      sampler.WalkPath(path,
        s.Spacing,
        s.CellSize,
        [&](size_t i, double t)
        {
          const glm::dvec3 c = path[i] + t * (path[i + 1] - path[i]);
          const double cc[3] = { c.x, c.y, c.z };
          const double f = length > 0.0
            ? std::min(1.0, (walked[i] + t * (walked[i + 1] - walked[i])) / length)
            : 1.0;
          out.Add(v, ids[k - 1], ids[k], f, cc, last);
          std::copy(cc, cc + 3, last);
          const vtkIdType added = out.Points->GetNumberOfPoints() - 1;
          return out.Radius->GetValue(added) * (s.ByPressure ? out.Pressure->GetValue(added) : 1.0);
        });
    }
  }
}
}

//------------------------------------------------------------------------------
vtkOFBPaintFilter::vtkOFBPaintFilter()
  : Brush(vtkSmartPointer<vtkOFBBrush>::New())
  , Painter(vtkSmartPointer<vtkOFBPainter>::New())
  , NumberOfChangedSamples(0)
{
  this->SetNumberOfInputPorts(2);
}

//------------------------------------------------------------------------------
vtkOFBPaintFilter::~vtkOFBPaintFilter() = default;

//------------------------------------------------------------------------------
void vtkOFBPaintFilter::SetStrokesConnection(vtkAlgorithmOutput* output)
{
  this->SetInputConnection(1, output);
}

//------------------------------------------------------------------------------
void vtkOFBPaintFilter::SetStrokesData(vtkPolyData* strokes)
{
  this->SetInputDataInternal(1, strokes);
}

//------------------------------------------------------------------------------
void vtkOFBPaintFilter::SetBrush(vtkOFBBrush* brush)
{
  if (this->Brush != brush)
  {
    this->Brush = brush;
    this->Modified();
  }
}

//------------------------------------------------------------------------------
vtkOFBBrush* vtkOFBPaintFilter::GetBrush() const
{
  return this->Brush;
}

//------------------------------------------------------------------------------
void vtkOFBPaintFilter::SetPainter(vtkOFBPainter* painter)
{
  if (this->Painter != painter)
  {
    this->Painter = painter;
    this->Modified();
  }
}

//------------------------------------------------------------------------------
vtkOFBPainter* vtkOFBPaintFilter::GetPainter() const
{
  return this->Painter;
}

//------------------------------------------------------------------------------
vtkMTimeType vtkOFBPaintFilter::GetMTime()
{
  vtkMTimeType t = this->Superclass::GetMTime();
  t = this->Brush ? std::max(t, this->Brush->GetMTime()) : t;
  return this->Painter ? std::max(t, this->Painter->GetMTime()) : t;
}

//------------------------------------------------------------------------------
int vtkOFBPaintFilter::FillInputPortInformation(int port, vtkInformation* info)
{
  if (port == 0)
  {
    info->Set(vtkAlgorithm::INPUT_REQUIRED_DATA_TYPE(), "vtkOFB");
  }
  else
  {
    info->Set(vtkAlgorithm::INPUT_REQUIRED_DATA_TYPE(), "vtkPolyData");
    info->Set(vtkAlgorithm::INPUT_IS_OPTIONAL(), 1);
  }
  return 1;
}

//------------------------------------------------------------------------------
vtkSmartPointer<vtkPolyData> vtkOFBPaintFilter::GetStrokes(vtkPolyData* strokes)
{
  return strokes;
}

//------------------------------------------------------------------------------
vtkSmartPointer<vtkPolyData> vtkOFBPaintFilter::MakeDabs(vtkPolyData* strokes, vtkOFB* ofb)
{
  vtkOFBDabArrays arrays{ strokes, std::string() };
  StrokeValues v{ strokes,
    this->Brush,
    arrays.Get("Radius", 1),
    arrays.Get("Color", 3),
    arrays.Get("Strength", 1),
    arrays.Get("Pressure", 1),
    1.0 };
  if (!arrays.Error.empty())
  {
    vtkErrorMacro("Strokes: " << arrays.Error);
    return nullptr;
  }
  if (v.Color && v.Color->GetDataType() == VTK_UNSIGNED_CHAR)
  {
    v.ColorScale = 1.0 / 255.0;
  }
  const std::string error = CheckPoints(strokes, v);
  if (!error.empty())
  {
    vtkErrorMacro(<< error);
    return nullptr;
  }

  const std::vector<std::pair<vtkIdType, vtkIdType>> segments = Segments(strokes);
  std::vector<glm::dvec3> at;
  std::vector<std::vector<glm::dvec3>> paths; // per segment of the polylines, in order
  PlaceOnSurface(
    strokes, segments, ofb, this->Painter->GetFollowSurface(), this->Exchange, at, paths);
  const DabSpacing spacing{
    this->Painter->GetSpacing(), ofb->GetCellSize(), this->Brush->GetPressureAffectsRadius()
  };
  const double expected = MostDabs(v, spacing, segments, paths);
  if (expected > vtkOFBMaximumStrokeDabs)
  {
    vtkErrorMacro("The strokes would place about " << expected << " dabs, more than "
                                                   << vtkOFBMaximumStrokeDabs
                                                   << " (radii too small for their length).");
    return nullptr;
  }

  DabArrays out;
  PlaceDabs(strokes, v, spacing, at, paths, out);
  auto dabs = vtkSmartPointer<vtkPolyData>::New();
  dabs->SetPoints(out.Points);
  vtkPointData* dpd = dabs->GetPointData();
  dpd->AddArray(out.Radius);
  dpd->AddArray(out.Pressure);
  dpd->AddArray(out.Previous);
  if (v.Strength)
  {
    dpd->AddArray(out.Strength);
  }
  if (v.Color)
  {
    dpd->AddArray(out.Color);
  }
  return dabs;
}

//------------------------------------------------------------------------------
int vtkOFBPaintFilter::RequestData(vtkInformation*,
  vtkInformationVector** inInfo,
  vtkInformationVector* outInfo)
{
  vtkOFB* input = vtkOFB::GetData(inInfo[0]);
  vtkSmartPointer<vtkPolyData> strokes = this->GetStrokes(vtkPolyData::GetData(inInfo[1]));
  vtkOFB* output = vtkOFB::GetData(outInfo);
  this->NumberOfChangedSamples = 0;
  if (!output)
  {
    return 0;
  }
  output->Initialize();
  // A distributed OFB's piece may have no samples: it takes part in the walks.
  const bool emptyPiece = !input || input->GetNumberOfSamples() == 0;
  if (emptyPiece && !this->Exchange)
  {
    vtkErrorMacro("The input OFB is missing or has no samples: empty output.");
    return 1;
  }
  if (!this->Brush || !this->Painter)
  {
    vtkErrorMacro("No brush or no painter: empty output.");
    return 1;
  }
  // The strokes' vertices and polylines index their points and per-point arrays (and
  // cells without points to name are bad input too, not an empty stroke).
  std::string error;
  if (strokes && !vtkOFBCheckCellPointIds(strokes, error))
  {
    vtkErrorMacro("The strokes (input port 1) are invalid: " << error << ".");
    return 1;
  }
  vtkSmartPointer<vtkPolyData> dabs;
  if (strokes && strokes->GetNumberOfPoints() > 0)
  {
    vtkNew<vtkOFB> none;
    dabs = this->MakeDabs(strokes, input ? input : none.Get());
    if (!dabs)
    {
      return 1; // the error is reported
    }
  }
  if (emptyPiece)
  {
    if (input)
    {
      output->ShallowCopy(input);
    }
    return 1;
  }

  // A painted copy: the painted array deep, the rest shared.
  output->ShallowCopy(input);
  const char* painted = this->Brush->GetTarget() == vtkOFBBrush::TARGET_NORMAL
    ? vtkOFB::NormalsArrayName()
    : vtkOFB::ColorsArrayName();
  vtkPointData* inPd = input->GetSampleData();
  if (vtkDataArray* array = inPd->GetArray(painted))
  {
    auto copy = vtkSmartPointer<vtkDataArray>::Take(array->NewInstance());
    copy->DeepCopy(array);
    vtkPointData* outPd = output->GetSampleData();
    outPd->AddArray(copy);
    if (inPd->GetScalars() == array)
    {
      outPd->SetScalars(copy);
    }
    if (inPd->GetNormals() == array)
    {
      outPd->SetNormals(copy);
    }
  }
  if (!dabs || dabs->GetNumberOfPoints() == 0)
  {
    return 1;
  }

  vtkNew<vtkOFBPainter> painter;
  painter->CopySettings(this->Painter);
  painter->SetOFB(output);
  painter->SetBrush(this->Brush);
  painter->SetUndoLimit(0);
  vtkNew<vtkCallbackCommand> progress;
  progress->SetClientData(this);
  progress->SetCallback([](vtkObject*, unsigned long, void* self, void* data)
    { static_cast<vtkOFBPaintFilter*>(self)->UpdateProgress(*static_cast<double*>(data)); });
  painter->AddObserver(vtkCommand::ProgressEvent, progress);
  vtkNew<vtkCallbackCommand> errors;
  errors->SetClientData(this);
  errors->SetCallback(
    [](vtkObject*, unsigned long, void* self, void* data)
    {
      vtkErrorWithObjectMacro(static_cast<vtkOFBPaintFilter*>(self),
        << (data ? static_cast<const char*>(data) : "painting failed"));
    });
  painter->AddObserver(vtkCommand::ErrorEvent, errors);
  this->NumberOfChangedSamples = painter->Dabs(dabs);
  this->UpdateProgress(1.0);
  return 1;
}

//------------------------------------------------------------------------------
void vtkOFBPaintFilter::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Brush: " << this->Brush.GetPointer() << "\n";
  os << indent << "Painter: " << this->Painter.GetPointer() << "\n";
  os << indent << "NumberOfChangedSamples: " << this->NumberOfChangedSamples << "\n";
}
