// The distributed OFB filters under MPI against one process, in one run: every process
// samples, LICs and paints its piece (vtkExtractPolyDataPiece with ghost levels) of a
// sphere; the first process also runs the same pipeline on the whole sphere with no
// controller, gathers the owned samples of every piece and compares.
//
//   mpirun -np N TestOFBPDistributed [--empty-last]
//
// --empty-last: the last process has an empty piece (the others share the sphere).
// --bad-input: a resolution out of range, then a surface without a vector field for the
// LIC: every process reports the error, outputs nothing, and none waits for another.
// Exit status 0 when every check holds, on every process.
#include "vtkCellData.h"
#include "vtkDataSetAttributes.h"
#include "vtkExtractPolyDataPiece.h"
#include "vtkFloatArray.h"
#include "vtkMPIController.h"
#include "vtkMath.h"
#include "vtkNew.h"
#include "vtkOFB.h"
#include "vtkOFBBrush.h"
#include "vtkOFBLIC.h"
#include "vtkOFBPLIC.h"
#include "vtkOFBPPaintFilter.h"
#include "vtkOFBPSampler.h"
#include "vtkOFBPTestSupport.h"
#include "vtkOFBPaintFilter.h"
#include "vtkOFBPainter.h"
#include "vtkOFBSampler.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkTypeUInt32Array.h"
#include "vtkUnsignedCharArray.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <vector>

namespace
{
constexpr int Fields = 14; // cell, depth, height, normal (3), LIC, fast LIC, colour (4), piece
constexpr int Resolution = 96;
constexpr int GhostLevels = 6;

/// A sphere without normals (the sampler computes them: across piece borders through
/// the ghost cells), with a tangential swirl "Field" and a scalar "Height".
vtkSmartPointer<vtkPolyData> MakeSphere()
{
  vtkSmartPointer<vtkPolyData> mesh = vtkofbtest::MakeSwirlSphere(false);
  const vtkIdType n = mesh->GetNumberOfPoints();
  vtkNew<vtkFloatArray> height;
  height->SetName("Height");
  height->SetNumberOfTuples(n);
  for (vtkIdType i = 0; i < n; ++i)
  {
    double p[3];
    mesh->GetPoint(i, p);
    height->SetValue(i, static_cast<float>(p[2] + 0.5 * p[0] * p[1]));
  }
  mesh->GetPointData()->AddArray(height);
  return mesh;
}

/// A great circle tilted across the sphere, as one polyline.
vtkSmartPointer<vtkPolyData> MakeStroke()
{
  vtkNew<vtkPoints> points;
  const int n = 48;
  for (int i = 0; i <= n; ++i)
  {
    const double t = 2.0 * vtkMath::Pi() * i / n;
    points->InsertNextPoint(
      0.5 * std::cos(t), 0.5 * std::sin(t) * std::cos(0.6), 0.5 * std::sin(t) * std::sin(0.6));
  }
  vtkNew<vtkCellArray> lines;
  lines->InsertNextCell(n + 1);
  for (int i = 0; i <= n; ++i)
  {
    lines->InsertCellPoint(i);
  }
  auto stroke = vtkSmartPointer<vtkPolyData>::New();
  stroke->SetPoints(points);
  stroke->SetLines(lines);
  return stroke;
}

/// The sampler, the plain LIC, the fast LIC and the paint filter of one pipeline.
struct Pipeline
{
  vtkNew<vtkOFBPSampler> Sampler;
  vtkNew<vtkOFBPLIC> LIC;
  vtkNew<vtkOFBPLIC> FastLIC;
  vtkNew<vtkOFBPPaintFilter> Paint;

  Pipeline(vtkMultiProcessController* controller, vtkPolyData* stroke, int ghostLevels)
  {
    this->Sampler->SetController(controller);
    this->Sampler->SetResolution(Resolution);
    for (vtkOFBPLIC* lic : { this->LIC.Get(), this->FastLIC.Get() })
    {
      lic->SetController(controller);
      lic->SetInputConnection(this->Sampler->GetOutputPort());
      lic->SetNumberOfSteps(10);
      lic->SetNumberOfGhostLevels(ghostLevels);
    }
    this->LIC->CacheStreamlinesOff();
    // The field scaled by its largest magnitude over every process.
    this->LIC->NormalizeVectorsOff();
    this->Paint->SetController(controller);
    this->Paint->SetInputConnection(this->LIC->GetOutputPort());
    this->Paint->SetStrokesData(stroke);
    this->Paint->GetPainter()->SetFollowSurface(false);
    this->Paint->GetBrush()->SetRadius(0.06);
    this->Paint->GetBrush()->SetColor(1.0, 0.1, 0.1);
  }

  void Update(int piece, int pieces)
  {
    this->Paint->UpdatePiece(piece, pieces, 0);
    this->FastLIC->UpdatePiece(piece, pieces, 0);
  }

  /// The owned samples, Fields values each, in the order of their cells.
  std::vector<double> Owned(int rank) const
  {
    vtkOFB* painted = vtkOFB::SafeDownCast(this->Paint->GetOutputDataObject(0));
    vtkOFB* fast = vtkOFB::SafeDownCast(this->FastLIC->GetOutputDataObject(0));
    std::vector<double> out;
    if (!painted || painted->GetNumberOfSamples() == 0)
    {
      return out;
    }
    vtkPointData* pd = painted->GetSampleData();
    vtkDataArray* height = pd->GetArray("Height");
    vtkDataArray* normals = pd->GetArray(vtkOFB::NormalsArrayName());
    vtkDataArray* lic = pd->GetArray("LIC");
    vtkDataArray* fastLIC = fast->GetSampleData()->GetArray("LIC");
    vtkDataArray* colors = pd->GetArray(vtkOFB::ColorsArrayName());
    if (!height || !normals || !lic || !fastLIC || !colors)
    {
      std::printf("rank %d: a sample array is missing\n", rank);
      return out;
    }
    vtkofbtest::ForEachOwnedSample(painted,
      [&](vtkIdType c, vtkIdType i, float depth)
      {
        double nrm[3], rgba[4];
        normals->GetTuple(i, nrm);
        colors->GetTuple(i, rgba);
        const double row[Fields] = { static_cast<double>(c),
          depth,
          height->GetTuple1(i),
          nrm[0],
          nrm[1],
          nrm[2],
          lic->GetTuple1(i),
          fastLIC->GetTuple1(i),
          rgba[0],
          rgba[1],
          rgba[2],
          rgba[3],
          static_cast<double>(rank) };
        out.insert(out.end(), row, row + Fields);
      });
    return out;
  }

  /// Origin, cell size and dimensions of the sampler's output.
  std::vector<double> Frame() const
  {
    vtkOFB* ofb = this->Sampler->GetOutput();
    std::vector<double> f(ofb->GetOrigin(), ofb->GetOrigin() + 3);
    f.push_back(ofb->GetCellSize());
    for (int a = 0; a < 3; ++a)
    {
      f.push_back(static_cast<double>(ofb->GetDimensions()[a]));
    }
    return f;
  }
};

/// Rows sorted by cell, then depth, then the other values.
void Sort(std::vector<double>& rows)
{
  const size_t n = rows.size() / Fields;
  std::vector<std::vector<double>> r(n);
  for (size_t i = 0; i < n; ++i)
  {
    r[i].assign(rows.begin() + i * Fields, rows.begin() + (i + 1) * Fields - 1);
    r[i].push_back(rows[(i + 1) * Fields - 1]);
  }
  std::sort(r.begin(), r.end());
  rows.clear();
  for (const auto& row : r)
  {
    rows.insert(rows.end(), row.begin(), row.end());
  }
}

/// The first process: the gathered pieces against the one-process OFB. `control`: the
/// pieces had no ghost levels, and their plain LIC must differ near the borders (the
/// comparison sees the borders).
bool Compare(std::vector<double> pieces, std::vector<double> whole, int size, bool control)
{
  Sort(pieces);
  Sort(whole);
  const size_t n = whole.size() / Fields;
  bool ok = true;
  if (pieces.size() != whole.size())
  {
    std::printf(
      "FAIL samples: %zu owned by the pieces, %zu in one process\n", pieces.size() / Fields, n);
    return false;
  }
  double maxNormal = 0, maxHeight = 0, maxLIC = 0, sumFast = 0, maxColor = 0;
  size_t placement = 0, licOff = 0, fastOff = 0;
  double sw = 0, sp = 0, sww = 0, spp = 0, swp = 0;
  for (size_t i = 0; i < n; ++i)
  {
    const double* p = pieces.data() + i * Fields;
    const double* w = whole.data() + i * Fields;
    placement += p[0] != w[0] || p[1] != w[1];
    maxHeight = std::max(maxHeight, std::abs(p[2] - w[2]));
    for (int k = 3; k < 6; ++k)
    {
      maxNormal = std::max(maxNormal, std::abs(p[k] - w[k]));
    }
    const double dl = std::abs(p[6] - w[6]);
    maxLIC = std::max(maxLIC, dl);
    licOff += dl > 1e-3;
    const double df = std::abs(p[7] - w[7]);
    sumFast += df;
    fastOff += df > 0.1;
    sw += w[7];
    sp += p[7];
    sww += w[7] * w[7];
    spp += p[7] * p[7];
    swp += w[7] * p[7];
    for (int k = 8; k < 12; ++k)
    {
      maxColor = std::max(maxColor, std::abs(p[k] - w[k]));
    }
  }
  const double cov = swp / n - (sw / n) * (sp / n);
  const double corr =
    cov / std::sqrt((sww / n - (sw / n) * (sw / n)) * (spp / n - (sp / n) * (sp / n)));
  if (control)
  {
    std::printf(
      "without ghost levels: plain LIC max |diff| %.2g, %zu samples > 1e-3\n", maxLIC, licOff);
    return placement == 0 && licOff > 0;
  }
  std::printf("%d processes, %zu samples: placement differs at %zu; max |diff| height %.2g, "
              "normal %.2g, LIC %.2g (%zu samples > 1e-3), colour %.0f; fast LIC mean |diff| "
              "%.3g, %zu samples > 0.1, correlation %.4f\n",
    size,
    n,
    placement,
    maxHeight,
    maxNormal,
    maxLIC,
    licOff,
    maxColor,
    sumFast / n,
    fastOff,
    corr);
  ok = ok && placement == 0 && maxHeight <= 1e-6 && maxNormal <= 1e-5;
  // Plain LIC: the same streamlines up to float rounding of the normals.
  ok = ok && maxLIC <= 1e-3;
  ok = ok && maxColor == 0.0;
  // Fast LIC: seeds depend on the tile's samples; equal in distribution.
  ok = ok && sumFast / n <= 0.02 && corr >= 0.95;
  return ok;
}
}

/**
 * The distributed classes without a controller against the serial ones with the same
 * settings: every sample array equal, value for value.
 */
bool SameAsSerialClasses(Pipeline& whole, vtkPolyData* mesh, vtkPolyData* stroke)
{
  vtkNew<vtkOFBSampler> sampler;
  sampler->SetResolution(Resolution);
  sampler->SetInputData(mesh);
  vtkNew<vtkOFBLIC> lic;
  lic->SetInputConnection(sampler->GetOutputPort());
  lic->SetNumberOfSteps(10);
  lic->CacheStreamlinesOff();
  lic->NormalizeVectorsOff();
  vtkNew<vtkOFBPaintFilter> paint;
  paint->SetInputConnection(lic->GetOutputPort());
  paint->SetStrokesData(stroke);
  paint->GetPainter()->SetFollowSurface(false);
  paint->GetBrush()->SetRadius(0.06);
  paint->GetBrush()->SetColor(1.0, 0.1, 0.1);
  paint->Update();
  vtkOFB* serial = vtkOFB::SafeDownCast(paint->GetOutputDataObject(0));
  vtkOFB* distributed = vtkOFB::SafeDownCast(whole.Paint->GetOutputDataObject(0));
  bool same = serial->GetNumberOfSamples() == distributed->GetNumberOfSamples() &&
    serial->GetNumberOfSamples() > 0;
  for (const char* name : { "Height", "Normals", "LIC", "Colors" })
  {
    vtkDataArray* a = serial->GetSampleData()->GetArray(name);
    vtkDataArray* b = distributed->GetSampleData()->GetArray(name);
    bool equal = same && a && b && a->GetNumberOfComponents() == b->GetNumberOfComponents();
    for (vtkIdType i = 0; equal && i < a->GetNumberOfTuples(); ++i)
    {
      for (int c = 0; c < a->GetNumberOfComponents(); ++c)
      {
        equal = equal && a->GetComponent(i, c) == b->GetComponent(i, c);
      }
    }
    if (!equal)
    {
      std::printf("FAIL without a controller, \"%s\" differs from the serial classes'\n", name);
    }
    same = same && equal;
  }
  return same;
}

/// --bad-input: errors on every process (an empty piece too) give empty outputs, no hang.
bool RunBadInput(vtkMultiProcessController* controller, int pieces)
{
  const int rank = controller->GetLocalProcessId();
  vtkSmartPointer<vtkPolyData> mesh = MakeSphere();
  vtkNew<vtkPolyData> noField;
  noField->ShallowCopy(mesh);
  noField->GetPointData()->SetVectors(nullptr);
  noField->GetPointData()->RemoveArray("Field");
  vtkNew<vtkPolyData> none;
  bool ok = true;
  for (int bad = 0; bad < 2; ++bad)
  {
    Pipeline pipeline(controller, none, GhostLevels);
    vtkNew<vtkExtractPolyDataPiece> extract;
    extract->SetInputData(bad == 0 ? mesh.GetPointer() : noField.GetPointer());
    if (rank < pieces)
    {
      pipeline.Sampler->SetInputConnection(extract->GetOutputPort());
    }
    else
    {
      pipeline.Sampler->SetInputData(none);
    }
    pipeline.Sampler->SetResolution(bad == 0 ? 2 : Resolution);
    pipeline.Update(std::min(rank, pieces - 1), pieces);
    const vtkIdType sampled = pipeline.Sampler->GetOutput()->GetNumberOfSamples();
    const vtkIdType convolved =
      vtkOFB::SafeDownCast(pipeline.LIC->GetOutputDataObject(0))->GetNumberOfSamples();
    // A resolution out of range: no samples; no field: samples, but no LIC.
    const bool expected = convolved == 0 && (bad == 1 || sampled == 0);
    std::printf("rank %d, %s: %lld samples, %lld with LIC%s\n",
      rank,
      bad == 0 ? "resolution 2" : "no field",
      static_cast<long long>(sampled),
      static_cast<long long>(convolved),
      expected ? "" : " FAIL");
    ok = ok && expected;
  }
  return ok;
}

int main(int argc, char* argv[])
{
  vtkSmartPointer<vtkMPIController> controller = vtkofbtest::StartMPI(&argc, &argv);
  const int rank = controller->GetLocalProcessId();
  const int size = controller->GetNumberOfProcesses();
  const int pieces = vtkofbtest::NumberOfPieces(controller, argc, argv);
  if (vtkofbtest::HasFlag(argc, argv, "--bad-input"))
  {
    return vtkofbtest::FinishAll(controller, RunBadInput(controller, pieces));
  }

  vtkSmartPointer<vtkPolyData> mesh = MakeSphere();
  vtkSmartPointer<vtkPolyData> stroke = MakeStroke();
  vtkNew<vtkPolyData> none;

  // This process's piece, with `ghostLevels` ghost levels for the LIC; the stroke is
  // given on the first process only. The owned samples and the frames gathered on the
  // first process.
  std::vector<double> frames(7 * size);
  auto runPieces = [&](int ghostLevels)
  {
    Pipeline distributed(
      controller, rank == 0 ? stroke.GetPointer() : none.GetPointer(), ghostLevels);
    vtkNew<vtkExtractPolyDataPiece> extract;
    if (rank < pieces)
    {
      extract->SetInputData(mesh);
      distributed.Sampler->SetInputConnection(extract->GetOutputPort());
    }
    else
    {
      distributed.Sampler->SetInputData(none);
    }
    distributed.Update(std::min(rank, pieces - 1), pieces);
    std::vector<double> gathered = vtkofbtest::GatherOnFirst(controller, distributed.Owned(rank));
    std::vector<double> frame = distributed.Frame();
    controller->Gather(frame.data(), frames.data(), 7, 0);
    return gathered;
  };
  std::vector<double> gathered = runPieces(GhostLevels);
  std::vector<double> unghosted = pieces > 1 ? runPieces(0) : std::vector<double>();

  int ok = 1;
  if (rank == 0)
  {
    Pipeline whole(nullptr, stroke, GhostLevels);
    whole.Sampler->SetInputData(mesh);
    whole.Update(0, 1);
    std::vector<double> reference = whole.Owned(0);
    const std::vector<double> wholeFrame = whole.Frame();
    if (!SameAsSerialClasses(whole, mesh, stroke))
    {
      ok = 0;
    }
    for (int r = 0; r < size; ++r)
    {
      if (!std::equal(wholeFrame.begin(), wholeFrame.end(), frames.begin() + 7 * r))
      {
        std::printf("FAIL frame of process %d differs from the one-process frame\n", r);
        ok = 0;
      }
    }
    ok = Compare(gathered, reference, size, false) && ok;
    if (pieces > 1 && !Compare(unghosted, reference, size, true))
    {
      std::printf("FAIL the plain LIC without ghost levels equals one process's: the "
                  "comparison does not see the piece borders\n");
      ok = 0;
    }
    std::printf("%s\n", ok ? "PASS" : "FAIL");
  }
  return vtkofbtest::FinishFirst(controller, ok);
}
