// Strokes that follow the surface across pieces, under MPI, against one process in one
// run: every process samples its piece of a pipe (vtkExtractPolyDataPiece with ghost
// levels, vtkOFBPSampler) and paints it with vtkOFBPPaintFilter, FollowSurface on (the
// default), strokes given on the first process: a helix around the pipe, a ring of three
// points a third of the way round from each other (each segment walks around the wall,
// where its chord crosses the inside), a stroke through points inside and outside the
// wall (moved onto it) and a single dab. The strokes carry per-point colours and radii,
// so a dab placed elsewhere along a path paints another colour. The first process also
// paints the whole pipe with no controller, gathers every piece's owned samples and
// compares their colours, which must be equal.
//
//   mpirun -np N TestOFBPStrokes [--empty-last] [--bad-input] [--many]
//
// --empty-last: the last process has an empty piece (the others share the pipe).
// --many: also a stroke of 300 points a few cells apart winding around the pipe, so that
// the first rounds of steps have more walks than one all-gather of candidates takes (the
// candidates then go through all-reduces), and the last rounds fewer.
// --bad-input: no process has samples (a resolution out of range), then a stroke point
// that is not finite: every process reports the error and outputs an empty OFB, and none
// waits for another.
// Exit status 0 when every check holds, on every process.
#include "vtkCellArray.h"
#include "vtkCommunicator.h"
#include "vtkDataSetAttributes.h"
#include "vtkExtractPolyDataPiece.h"
#include "vtkFloatArray.h"
#include "vtkMPIController.h"
#include "vtkMath.h"
#include "vtkNew.h"
#include "vtkOFB.h"
#include "vtkOFBBrush.h"
#include "vtkOFBPPaintFilter.h"
#include "vtkOFBPSampler.h"
#include "vtkOFBPTestSupport.h"
#include "vtkOFBPainter.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkTypeUInt32Array.h"
#include "vtkUnsignedCharArray.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <vector>

namespace
{
constexpr int Resolution = 96;
constexpr int GhostLevels = 2;
constexpr double PipeRadius = 0.3;
constexpr double HalfLength = 0.8;
constexpr int Fields = 8; // cell, depth, colour (4), painted (0 or 1), process

/// An open pipe along x, of triangles, without normals (the sampler computes them).
vtkSmartPointer<vtkPolyData> MakePipe()
{
  const int around = 96, along = 48;
  vtkNew<vtkPoints> points;
  for (int j = 0; j <= along; ++j)
  {
    for (int i = 0; i < around; ++i)
    {
      const double t = 2.0 * vtkMath::Pi() * i / around;
      points->InsertNextPoint(-HalfLength + 2.0 * HalfLength * j / along,
        PipeRadius * std::cos(t),
        PipeRadius * std::sin(t));
    }
  }
  vtkNew<vtkCellArray> triangles;
  for (int j = 0; j < along; ++j)
  {
    for (int i = 0; i < around; ++i)
    {
      const vtkIdType a = j * around + i, b = j * around + (i + 1) % around;
      const vtkIdType c = a + around, d = b + around;
      const vtkIdType first[3] = { a, b, d };
      const vtkIdType second[3] = { a, d, c };
      triangles->InsertNextCell(3, first);
      triangles->InsertNextCell(3, second);
    }
  }
  auto pipe = vtkSmartPointer<vtkPolyData>::New();
  pipe->SetPoints(points);
  pipe->SetPolys(triangles);
  return pipe;
}

/// A point at angle t around the pipe, at distance r from its axis.
std::array<double, 3> Around(double x, double t, double r)
{
  return { x, r * std::cos(t), r * std::sin(t) };
}

/// The strokes, with per-point "Color" (unsigned char) and "Radius"; `many`: also a
/// stroke of 300 points.
vtkSmartPointer<vtkPolyData> MakeStrokes(bool many)
{
  vtkNew<vtkPoints> points;
  vtkNew<vtkUnsignedCharArray> color;
  color->SetName("Color");
  color->SetNumberOfComponents(3);
  vtkNew<vtkFloatArray> radius;
  radius->SetName("Radius");
  vtkNew<vtkCellArray> lines;
  vtkNew<vtkCellArray> verts;
  auto add = [&](const std::array<double, 3>& p, double f)
  {
    points->InsertNextPoint(p.data());
    const unsigned char c[3] = {
      static_cast<unsigned char>(255 * f), 40, static_cast<unsigned char>(255 * (1 - f))
    };
    color->InsertNextTypedTuple(c);
    radius->InsertNextValue(static_cast<float>(0.03 + 0.02 * f));
    return points->GetNumberOfPoints() - 1;
  };
  // A helix: one and a half turns along the pipe.
  const int n = 40;
  lines->InsertNextCell(n + 1);
  for (int i = 0; i <= n; ++i)
  {
    const double f = double(i) / n;
    lines->InsertCellPoint(add(Around(-0.7 + 1.4 * f, 3.0 * vtkMath::Pi() * f, PipeRadius), f));
  }
  // A ring of three points: each segment's chord crosses the inside of the pipe.
  lines->InsertNextCell(4);
  for (int i = 0; i <= 3; ++i)
  {
    lines->InsertCellPoint(
      add(Around(0.35, 0.3 + 2.0 * vtkMath::Pi() * i / 3.0, PipeRadius), i / 3.0));
  }
  // Points inside and outside the wall, moved onto it, and a long segment along the pipe.
  lines->InsertNextCell(4);
  lines->InsertCellPoint(add(Around(-0.6, 1.0, 0.05), 0.0));
  lines->InsertCellPoint(add(Around(-0.2, 2.2, 0.45), 0.4));
  lines->InsertCellPoint(add(Around(0.1, 4.0, 0.2), 0.7));
  lines->InsertCellPoint(add(Around(0.7, 4.3, PipeRadius), 1.0));
  if (many)
  {
    // 300 points about 4 cells apart, winding around the pipe along its length.
    const int m = 300;
    lines->InsertNextCell(m);
    for (int i = 0; i < m; ++i)
    {
      const double f = double(i) / (m - 1);
      lines->InsertCellPoint(add(Around(-0.75 + 1.5 * f, 0.21 * i, PipeRadius), f));
    }
  }
  // A single dab, off the surface.
  verts->InsertNextCell(1);
  verts->InsertCellPoint(add(Around(-0.4, 5.5, 0.35), 0.5));
  auto strokes = vtkSmartPointer<vtkPolyData>::New();
  strokes->SetPoints(points);
  strokes->SetLines(lines);
  strokes->SetVerts(verts);
  strokes->GetPointData()->AddArray(color);
  strokes->GetPointData()->AddArray(radius);
  return strokes;
}

/// The sampler and the paint filter of one pipeline.
struct Pipeline
{
  vtkNew<vtkOFBPSampler> Sampler;
  vtkNew<vtkOFBPPaintFilter> Paint;

  Pipeline(vtkMultiProcessController* controller, vtkPolyData* strokes)
  {
    this->Sampler->SetController(controller);
    this->Sampler->SetResolution(Resolution);
    this->Paint->SetController(controller);
    this->Paint->SetInputConnection(this->Sampler->GetOutputPort());
    this->Paint->SetStrokesData(strokes);
    this->Paint->GetBrush()->SetColor(0.9, 0.9, 0.1);
  }

  /// The owned samples, Fields values each, in the order of their cells.
  std::vector<double> Owned(int rank) const
  {
    vtkOFB* painted = vtkOFB::SafeDownCast(this->Paint->GetOutputDataObject(0));
    std::vector<double> out;
    if (!painted || painted->GetNumberOfSamples() == 0)
    {
      return out;
    }
    vtkPointData* pd = painted->GetSampleData();
    vtkDataArray* colors = pd->GetArray(vtkOFB::ColorsArrayName());
    vtkDataArray* before =
      this->Sampler->GetOutput()->GetSampleData()->GetArray(vtkOFB::ColorsArrayName());
    if (!colors || !before)
    {
      std::printf("rank %d: no colours\n", rank);
      return out;
    }
    vtkofbtest::ForEachOwnedSample(painted,
      [&](vtkIdType c, vtkIdType i, float depth)
      {
        double rgba[4], unpainted[4];
        colors->GetTuple(i, rgba);
        before->GetTuple(i, unpainted);
        const bool changed = !std::equal(rgba, rgba + 4, unpainted);
        const double row[Fields] = { static_cast<double>(c),
          depth,
          rgba[0],
          rgba[1],
          rgba[2],
          rgba[3],
          changed ? 1.0 : 0.0,
          static_cast<double>(rank) };
        out.insert(out.end(), row, row + Fields);
      });
    return out;
  }
};

/// Rows sorted by cell, then depth.
std::vector<std::array<double, Fields>> Rows(const std::vector<double>& values)
{
  std::vector<std::array<double, Fields>> rows(values.size() / Fields);
  for (size_t i = 0; i < rows.size(); ++i)
  {
    std::copy(values.begin() + i * Fields, values.begin() + (i + 1) * Fields, rows[i].begin());
  }
  std::sort(rows.begin(), rows.end());
  return rows;
}

/// The first process: the gathered pieces against one process.
bool Compare(const std::vector<double>& gathered,
  const std::vector<double>& reference,
  int size,
  int pieces)
{
  const auto owned = Rows(gathered);
  const auto whole = Rows(reference);
  if (owned.size() != whole.size())
  {
    std::printf(
      "FAIL samples: %zu owned by the pieces, %zu in one process\n", owned.size(), whole.size());
    return false;
  }
  size_t painted = 0, placement = 0, differ = 0;
  double largest = 0.0;
  std::vector<size_t> paintedBy(size, 0);
  for (size_t i = 0; i < whole.size(); ++i)
  {
    const auto& p = owned[i];
    const auto& w = whole[i];
    placement += p[0] != w[0] || p[1] != w[1];
    const bool isPainted = w[6] != 0.0;
    bool same = true;
    for (int k = 0; k < 4; ++k)
    {
      same = same && p[2 + k] == w[2 + k];
      largest = std::max(largest, std::abs(p[2 + k] - w[2 + k]));
    }
    painted += isPainted;
    differ += !same;
    if (isPainted)
    {
      ++paintedBy[static_cast<int>(p[Fields - 1])];
    }
  }
  int processesPainted = 0;
  std::printf("%d processes, %zu samples, %zu painted by one process; painted samples owned "
              "by each process:",
    size,
    whole.size(),
    painted);
  for (int r = 0; r < size; ++r)
  {
    std::printf(" %zu", paintedBy[r]);
    processesPainted += paintedBy[r] > 0;
  }
  std::printf("; placement differs at %zu, colour at %zu (largest |diff| %.0f of 255)\n",
    placement,
    differ,
    largest);
  bool ok = placement == 0 && differ == 0 && painted > 500;
  // The strokes cross the piece borders: more than one process owns painted samples.
  if (pieces > 1 && processesPainted < 2)
  {
    std::printf("FAIL the strokes do not cross a piece border\n");
    ok = false;
  }
  return ok;
}
}

/// --bad-input: errors on every process (an empty piece too) give empty outputs, no hang.
bool RunBadInput(vtkMultiProcessController* controller, int pieces, vtkPolyData* pipe)
{
  const int rank = controller->GetLocalProcessId();
  vtkNew<vtkPolyData> none;
  vtkSmartPointer<vtkPolyData> strokes = MakeStrokes(false);
  vtkNew<vtkPolyData> notFinite;
  notFinite->DeepCopy(strokes);
  notFinite->GetPoints()->SetPoint(3, std::nan(""), 0.0, 0.0);
  bool ok = true;
  for (int bad = 0; bad < 2; ++bad)
  {
    vtkPolyData* given = bad == 0 ? strokes.GetPointer() : notFinite.GetPointer();
    Pipeline pipeline(controller, rank == 0 ? given : none.GetPointer());
    pipeline.Sampler->SetResolution(bad == 0 ? 2 : Resolution);
    vtkNew<vtkExtractPolyDataPiece> extract;
    extract->SetInputData(pipe);
    if (rank < pieces)
    {
      pipeline.Sampler->SetInputConnection(extract->GetOutputPort());
    }
    else
    {
      pipeline.Sampler->SetInputData(none);
    }
    pipeline.Paint->UpdatePiece(std::min(rank, pieces - 1), pieces, GhostLevels);
    const vtkIdType painted =
      vtkOFB::SafeDownCast(pipeline.Paint->GetOutputDataObject(0))->GetNumberOfSamples();
    std::printf("rank %d, %s: %lld samples out%s\n",
      rank,
      bad == 0 ? "resolution 2" : "a stroke point not finite",
      static_cast<long long>(painted),
      painted == 0 ? "" : " FAIL");
    ok = ok && painted == 0;
  }
  return ok;
}

int main(int argc, char* argv[])
{
  vtkSmartPointer<vtkMPIController> controller = vtkofbtest::StartMPI(&argc, &argv);
  const int rank = controller->GetLocalProcessId();
  const int size = controller->GetNumberOfProcesses();
  const int pieces =
    vtkofbtest::NumberOfPieces(controller, vtkofbtest::HasFlag(argc, argv, "--empty-last"));
  vtkSmartPointer<vtkPolyData> pipe = MakePipe();
  if (vtkofbtest::HasFlag(argc, argv, "--bad-input"))
  {
    return vtkofbtest::FinishAll(controller, RunBadInput(controller, pieces, pipe));
  }
  vtkSmartPointer<vtkPolyData> strokes = MakeStrokes(vtkofbtest::HasFlag(argc, argv, "--many"));
  vtkNew<vtkPolyData> none;

  // This process's piece, painted with the strokes given on the first process.
  Pipeline distributed(controller, rank == 0 ? strokes.GetPointer() : none.GetPointer());
  vtkNew<vtkExtractPolyDataPiece> extract;
  if (rank < pieces)
  {
    extract->SetInputData(pipe);
    distributed.Sampler->SetInputConnection(extract->GetOutputPort());
  }
  else
  {
    distributed.Sampler->SetInputData(none);
  }
  distributed.Paint->UpdatePiece(std::min(rank, pieces - 1), pieces, GhostLevels);
  const std::vector<double> owned = distributed.Owned(rank);
  const vtkIdType reductions = distributed.Paint->GetNumberOfStrokeReductions();
  std::printf("rank %d: %zu owned samples, %lld changed, %lld all-reduces for the paths\n",
    rank,
    owned.size() / Fields,
    static_cast<long long>(distributed.Paint->GetNumberOfChangedSamples()),
    static_cast<long long>(reductions));
  // On more than one process the paths are walked together (the frame, the points, then
  // a round of steps at least): 9 all-reduces or more, the same number on every process.
  vtkIdType fewest = 0, most = 0;
  controller->AllReduce(&reductions, &fewest, 1, vtkCommunicator::MIN_OP);
  controller->AllReduce(&reductions, &most, 1, vtkCommunicator::MAX_OP);
  const bool walked = fewest == most && (size == 1 ? most == 0 : most >= 9);

  const std::vector<double> gathered = vtkofbtest::GatherOnFirst(controller, owned);

  int ok = walked ? 1 : 0;
  if (!walked && rank == 0)
  {
    std::printf("FAIL all-reduces for the paths: %lld to %lld\n",
      static_cast<long long>(fewest),
      static_cast<long long>(most));
  }
  if (rank == 0)
  {
    Pipeline whole(nullptr, strokes);
    whole.Sampler->SetInputData(pipe);
    whole.Paint->Update();
    ok = Compare(gathered, whole.Owned(0), size, pieces) && ok ? 1 : 0;
    std::printf("%s\n", ok ? "PASS" : "FAIL");
  }
  return vtkofbtest::FinishFirst(controller, ok);
}
