// vtkOFBPainter against changes of its OFB during and between calls, two painters on
// one OFB, missing collaborators, out-of-range input (the sanitizer build runs these
// clean) and the limits on a call's work.
#include "vtkOFBTestUtilities.h"

#include "vtkCallbackCommand.h"
#include "vtkExecutive.h"
#include "vtkFloatArray.h"
#include "vtkIdTypeArray.h"
#include "vtkOFBBrush.h"
#include "vtkOFBDecalPatch.h"
#include "vtkOFBPaintFilter.h"
#include "vtkOFBPainter.h"
#include "vtkOFBTextureProjector.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkTypeUInt32Array.h"
#include "vtkUnsignedCharArray.h"

#include <gtest/gtest.h>

#include <chrono>
#include <cmath>
#include <functional>
#include <map>
#include <thread>

using namespace vtkofbtest;

namespace
{
vtkSmartPointer<vtkOFB> SphereOFB(int resolution)
{
  static std::map<int, vtkSmartPointer<vtkOFB>> cache;
  if (!cache[resolution])
  {
    cache[resolution] = Build(MakeSphere(1.0, 96), resolution);
  }
  auto copy = vtkSmartPointer<vtkOFB>::New();
  copy->DeepCopy(cache[resolution]);
  return copy;
}

// An OFB of one sample per cell of a 2 x 2 x 2 frame at `origin` (cell size 1), every
// sample at `depth` along its axis, with unit normals along the axes.
vtkSmartPointer<vtkOFB> TinyOFB(double origin, float depth)
{
  auto ofb = vtkSmartPointer<vtkOFB>::New();
  const double o[3] = { origin, -origin, origin };
  const vtkIdType dims[3] = { 2, 2, 2 };
  if (!ofb->SetFrame(o, 1.0, dims))
  {
    return nullptr;
  }
  const vtkIdType cells = ofb->GetNumberOfCells();
  for (vtkIdType c = 0; c <= cells; ++c)
  {
    ofb->GetCellOffsets()->SetValue(c, static_cast<vtkTypeUInt32>(c));
  }
  if (!ofb->AllocateSamples(cells))
  {
    return nullptr;
  }
  for (vtkIdType i = 0; i < cells; ++i)
  {
    ofb->GetDepths()->SetValue(i, depth);
  }
  ofb->BuildCellIndex();
  vtkNew<vtkFloatArray> normals;
  normals->SetName(vtkOFB::NormalsArrayName());
  normals->SetNumberOfComponents(3);
  normals->SetNumberOfTuples(cells);
  for (vtkIdType i = 0; i < cells; ++i)
  {
    normals->SetTuple3(i, 0.0, 0.0, 1.0);
  }
  ofb->GetSampleData()->AddArray(normals);
  return ofb;
}

// Calls `action` from the first progress event of `painter` (once).
struct ProgressAction
{
  std::function<void()> Action;
  bool Done = false;
  vtkNew<vtkCallbackCommand> Command;

  ProgressAction(vtkOFBPainter* painter, std::function<void()> action)
    : Action(std::move(action))
  {
    this->Command->SetClientData(this);
    this->Command->SetCallback(
      [](vtkObject*, unsigned long, void* cd, void*)
      {
        auto* self = static_cast<ProgressAction*>(cd);
        if (!self->Done)
        {
          self->Done = true;
          self->Action();
        }
      });
    painter->AddObserver(vtkCommand::ProgressEvent, this->Command);
  }
};

// A painter whose only reference to a large OFB (one dab reports progress) is its own.
vtkSmartPointer<vtkOFBPainter> BigPainter()
{
  auto painter = vtkSmartPointer<vtkOFBPainter>::New();
  painter->SetOFB(SphereOFB(640));
  painter->GetBrush()->SetRadius(10.0);
  painter->GetBrush()->SetColor(0, 0, 0);
  painter->GetBrush()->SetFalloffToConstant();
  return painter;
}

bool AllFinite(vtkDataArray* array)
{
  for (vtkIdType i = 0; array && i < array->GetNumberOfValues(); ++i)
  {
    if (!std::isfinite(array->GetComponent(i / array->GetNumberOfComponents(),
          static_cast<int>(i % array->GetNumberOfComponents()))))
    {
      return false;
    }
  }
  return true;
}
}

//------------------------------------------------------------------------------
TEST(PainterRobust, SetOFBFromAProgressObserverIsRefused)
{
  for (bool other : { false, true })
  {
    vtkSmartPointer<vtkOFBPainter> painter = BigPainter();
    vtkOFB* ofb = painter->GetOFB();
    const vtkIdType n = ofb->GetNumberOfSamples();
    vtkSmartPointer<vtkOFB> another = SphereOFB(64);
    vtkNew<MessageObserver> messages;
    messages->Watch(painter);
    ProgressAction action(painter,
      [&]()
      {
        EXPECT_TRUE(painter->IsPainting());
        painter->SetOFB(other ? another.Get() : nullptr);
      });
    EXPECT_EQ(painter->Dab(0, 0, 0), n);
    EXPECT_TRUE(action.Done);
    EXPECT_NE(messages->Errors.find("SetOFB"), std::string::npos);
    EXPECT_EQ(painter->GetOFB(), ofb);
    EXPECT_FALSE(painter->IsPainting());
    // Between calls it is followed.
    painter->SetOFB(another);
    painter->GetBrush()->SetRadius(0.3);
    EXPECT_GT(painter->Dab(0, 0, 1), 0);
  }
}

//------------------------------------------------------------------------------
TEST(PainterRobust, RebuildingTheOFBDuringACallIsRefused)
{
  vtkSmartPointer<vtkOFB> source = SphereOFB(64);
  const std::vector<std::pair<std::string, std::function<void(vtkOFB*)>>> changes = {
    { "Initialize", [](vtkOFB* ofb) { ofb->Initialize(); } },
    { "DeepCopy", [&](vtkOFB* ofb) { ofb->DeepCopy(source); } },
    { "ShallowCopy", [&](vtkOFB* ofb) { ofb->ShallowCopy(source); } },
  };
  for (const auto& change : changes)
  {
    vtkSmartPointer<vtkOFBPainter> painter = BigPainter();
    vtkOFB* ofb = painter->GetOFB();
    const vtkIdType n = ofb->GetNumberOfSamples();
    vtkNew<MessageObserver> messages;
    messages->Watch(ofb);
    ProgressAction action(painter, [&]() { change.second(ofb); });
    EXPECT_EQ(painter->Dab(0, 0, 0), n) << change.first;
    EXPECT_TRUE(action.Done);
    EXPECT_NE(messages->Errors.find(change.first + ": the OFB is being painted"), std::string::npos)
      << messages->Errors;
    EXPECT_EQ(ofb->GetNumberOfSamples(), n);
    EXPECT_FALSE(ofb->IsBeingWritten());
    // After the call the change goes through, and the painter follows it.
    change.second(ofb);
    painter->GetBrush()->SetRadius(0.3);
    const vtkIdType painted = painter->Dab(0, 0, 1);
    if (change.first == "Initialize")
    {
      EXPECT_EQ(painted, 0);
      EXPECT_EQ(painter->Undo(), 0);
    }
    else
    {
      EXPECT_GT(painted, 0);
      EXPECT_GT(painter->Undo(), 0);
    }
  }
}

//------------------------------------------------------------------------------
TEST(PainterRobust, ColorsRemovedDuringOrBetweenCalls)
{
  vtkSmartPointer<vtkOFBPainter> painter = BigPainter();
  vtkOFB* ofb = painter->GetOFB();
  const vtkIdType n = ofb->GetNumberOfSamples();
  ProgressAction action(
    painter, [&]() { ofb->GetSampleData()->RemoveArray(vtkOFB::ColorsArrayName()); });
  // The call ends in the array it started in, which the painter held.
  EXPECT_EQ(painter->Dab(0, 0, 0), n);
  EXPECT_TRUE(action.Done);
  EXPECT_EQ(ofb->GetSampleData()->GetArray(vtkOFB::ColorsArrayName()), nullptr);
  // The next call finds the OFB changed: the history goes, a new "Colors" is made.
  vtkNew<MessageObserver> messages;
  messages->Watch(painter);
  EXPECT_EQ(painter->Undo(), 0);
  EXPECT_NE(messages->Warnings.find("undo history is dropped"), std::string::npos);
  painter->GetBrush()->SetRadius(0.3);
  EXPECT_GT(painter->Dab(0, 0, 1), 0);
  ASSERT_NE(ofb->GetSampleData()->GetArray(vtkOFB::ColorsArrayName()), nullptr);
  // Removed between calls, with history: dropped, no stale read.
  ofb->GetSampleData()->RemoveArray(vtkOFB::ColorsArrayName());
  EXPECT_EQ(painter->Undo(), 0);
  EXPECT_EQ(painter->Redo(), 0);
  EXPECT_GT(painter->Dab(0, 1, 0), 0);
  EXPECT_GT(painter->Undo(), 0);
}

//------------------------------------------------------------------------------
TEST(PainterRobust, ChangesBetweenCallsAreFollowed)
{
  vtkSmartPointer<vtkOFB> small = SphereOFB(48);
  for (int variant = 0; variant < 4; ++variant)
  {
    vtkNew<vtkOFBPainter> painter;
    painter->SetOFB(SphereOFB(96));
    vtkOFB* ofb = painter->GetOFB();
    painter->GetBrush()->SetRadius(0.3);
    painter->GetBrush()->SetColor(0.2, 0.4, 0.6);
    EXPECT_GT(painter->Dab(0, 0, 1), 0);
    switch (variant)
    {
      case 0:
        ofb->Initialize();
        break;
      case 1:
        ofb->DeepCopy(small);
        break;
      case 2:
        ofb->ShallowCopy(small);
        break;
      default:
        ofb->GetSampleData()->RemoveArray(vtkOFB::ColorsArrayName());
        break;
    }
    vtkNew<MessageObserver> messages;
    messages->Watch(painter);
    EXPECT_EQ(painter->Undo(), 0) << variant;
    const vtkIdType painted = painter->Dab(0, 0, 1);
    EXPECT_EQ(painted > 0, variant != 0) << variant;
    EXPECT_EQ(painter->Undo(), painted) << variant;
  }
}

//------------------------------------------------------------------------------
TEST(PainterRobust, TwoPaintersOnOneOFB)
{
  vtkSmartPointer<vtkOFBPainter> first = BigPainter();
  vtkNew<vtkOFBPainter> second;
  second->SetOFB(first->GetOFB());
  vtkNew<MessageObserver> messages;
  messages->Watch(second);
  vtkIdType inner = -1;
  ProgressAction action(first, [&]() { inner = second->Dab(0, 0, 1); });
  EXPECT_GT(first->Dab(0, 0, 0), 0);
  EXPECT_EQ(inner, 0);
  EXPECT_NE(messages->Errors.find("being painted by another painter"), std::string::npos);
  // A painter called again from its own observer refuses too.
  vtkIdType again = -1;
  vtkNew<MessageObserver> own;
  own->Watch(first);
  ProgressAction reentry(first, [&]() { again = first->Dab(0, 0, 1); });
  first->GetBrush()->SetColor(1, 0, 0);
  EXPECT_GT(first->Dab(0, 0, 0), 0);
  EXPECT_EQ(again, 0);
  EXPECT_NE(own->Errors.find("in progress"), std::string::npos);

  // From two threads: each call paints or is refused whole; nothing crashes.
  vtkSmartPointer<vtkOFB> shared = SphereOFB(96);
  vtkNew<vtkOFBPainter> a;
  vtkNew<vtkOFBPainter> b;
  vtkNew<MessageObserver> quiet;
  quiet->Watch(a);
  quiet->Watch(b);
  a->SetOFB(shared);
  b->SetOFB(shared);
  a->GetBrush()->SetRadius(0.2);
  b->GetBrush()->SetRadius(0.2);
  auto run = [](vtkOFBPainter* p, double z)
  {
    for (int k = 0; k < 200; ++k)
    {
      p->Dab(std::cos(k * 0.1), std::sin(k * 0.1), z);
    }
  };
  std::thread ta(run, a.Get(), 0.5);
  std::thread tb(run, b.Get(), -0.5);
  ta.join();
  tb.join();
  EXPECT_FALSE(shared->IsBeingWritten());
}

//------------------------------------------------------------------------------
TEST(PainterRobust, MissingBrushOrOFBIsAnError)
{
  vtkNew<vtkOFBPainter> painter;
  painter->SetOFB(SphereOFB(48));
  painter->SetBrush(nullptr);
  vtkNew<MessageObserver> messages;
  messages->Watch(painter);
  vtkNew<vtkPoints> points;
  points->InsertNextPoint(0, 0, 1);
  vtkNew<vtkPolyData> dabs;
  dabs->SetPoints(points);
  EXPECT_EQ(painter->Dab(0, 0, 1), 0);
  EXPECT_EQ(painter->Dabs(points), 0);
  EXPECT_EQ(painter->Dabs(dabs), 0);
  EXPECT_EQ(painter->StrokeTo(0, 0, 1), 0);
  EXPECT_EQ(painter->StrokeTo(0, 0.1, 1), 0);
  painter->EndStroke();
  size_t count = 0;
  for (size_t at = messages->Errors.find("no brush"); at != std::string::npos;
       at = messages->Errors.find("no brush", at + 1))
  {
    ++count;
  }
  EXPECT_EQ(count, 5u) << messages->Errors;
  EXPECT_FALSE(painter->CanUndo());

  painter->SetBrush(vtkNew<vtkOFBBrush>());
  painter->SetOFB(nullptr);
  messages->Clear();
  EXPECT_EQ(painter->Dab(0, 0, 1), 0);
  EXPECT_EQ(painter->Dabs(points), 0);
  EXPECT_EQ(painter->Dabs(dabs), 0);
  EXPECT_EQ(painter->StrokeTo(0, 0, 1), 0);
  painter->EndStroke();
  vtkNew<vtkIdTypeArray> ids;
  ids->InsertNextValue(0);
  vtkNew<vtkUnsignedCharArray> colors;
  colors->SetNumberOfComponents(4);
  colors->InsertNextTuple4(1, 2, 3, 4);
  EXPECT_EQ(painter->SetSampleColors(ids, colors), 0);
  EXPECT_EQ(painter->Undo(), 0);
  EXPECT_EQ(painter->Redo(), 0);
  painter->ClearHistory();
  painter->ResetInitialValues();
  EXPECT_NE(messages->Errors.find("No OFB"), std::string::npos);
}

//------------------------------------------------------------------------------
TEST(PainterRobust, FarAndTinyInputIsDefined)
{
  vtkSmartPointer<vtkOFB> ofb = SphereOFB(64);
  vtkNew<vtkOFBPainter> painter;
  painter->SetOFB(ofb);
  painter->GetBrush()->SetRadius(0.3);
  painter->GetBrush()->SetColor(0.2, 0.4, 0.6);
  vtkDataArray* normals = ofb->GetSampleData()->GetArray(vtkOFB::NormalsArrayName());
  ASSERT_NE(normals, nullptr);
  vtkNew<MessageObserver> messages;
  messages->Watch(painter);
  // Far centres paint nothing; a tiny radius paints at most a sample.
  EXPECT_EQ(painter->Dab(1e308, -1e308, 1e308), 0);
  EXPECT_EQ(painter->Dab(-1e308, 1e308, -1e308), 0);
  painter->MirrorXOn();
  EXPECT_EQ(painter->Dab(1e308, 0, 1), 0);
  painter->MirrorXOff();
  painter->GetBrush()->SetRadius(1e-300);
  EXPECT_LE(painter->Dab(0, 0, 1), 1);
  vtkNew<vtkPoints> points;
  points->InsertNextPoint(0, 0, 1);
  points->InsertNextPoint(1e308, 1e308, -1e308);
  points->InsertNextPoint(0, 1, 0);
  EXPECT_LE(painter->Dabs(points), 2);
  painter->GetBrush()->SetRadius(1e308);
  EXPECT_GT(painter->Dab(0, 0, 1), 0);
  EXPECT_TRUE(AllFinite(ofb->GetSampleData()->GetArray(vtkOFB::ColorsArrayName())));

  // A huge bump depth is clamped: the normals stay finite and unit.
  painter->GetBrush()->SetRadius(0.5);
  painter->GetBrush()->SetTargetToNormal();
  painter->GetBrush()->SetBumpDepth(1e308);
  EXPECT_EQ(painter->GetBrush()->GetBumpDepth(), 1000.0);
  painter->GetBrush()->SetBumpDepth(-1e308);
  EXPECT_EQ(painter->GetBrush()->GetBumpDepth(), -1000.0);
  EXPECT_GT(painter->Dab(0, 0, 1), 0);
  EXPECT_TRUE(AllFinite(normals));
  // A huge centre normal is not a direction: painted as without one.
  painter->GetBrush()->NormalAwareOn();
  vtkNew<vtkPolyData> dabs;
  dabs->SetPoints(points);
  vtkNew<vtkFloatArray> dabNormals;
  dabNormals->SetName("Normal");
  dabNormals->SetNumberOfComponents(3);
  for (int k = 0; k < 3; ++k)
  {
    dabNormals->InsertNextTuple3(3e38, 3e38, -3e38);
  }
  dabs->GetPointData()->AddArray(dabNormals);
  painter->Dabs(dabs);
  EXPECT_TRUE(AllFinite(normals));

  // OFBs far from the origin and samples at the far ends of float.
  for (double origin : { 1e308, -1e308, 0.0 })
  {
    for (float depth : { 0.5f, 3e38f, -3e38f })
    {
      vtkSmartPointer<vtkOFB> tiny = TinyOFB(origin, depth);
      ASSERT_NE(tiny, nullptr);
      vtkNew<vtkOFBPainter> p;
      p->SetOFB(tiny);
      for (double radius : { 1.0, 1e-300, 1e308 })
      {
        p->GetBrush()->SetRadius(radius);
        p->GetBrush()->SetTargetToColor();
        p->Dab(origin + 1.0, -origin + 1.0, origin + 1.0);
        p->Dab(0, 0, 0);
        p->Dab(1e308, -1e308, 1e308);
        p->GetBrush()->SetTargetToNormal();
        p->GetBrush()->SetBumpDepth(1e308);
        p->Dab(origin + 1.0, -origin + 1.0, origin + 1.0);
      }
      EXPECT_TRUE(AllFinite(tiny->GetSampleData()->GetArray(vtkOFB::NormalsArrayName())));
    }
  }
}

//------------------------------------------------------------------------------
TEST(PainterRobust, TooManyDabsAreRefusedFast)
{
  vtkNew<vtkOFBPainter> painter;
  painter->SetOFB(SphereOFB(48));
  painter->GetBrush()->SetRadius(0.05);
  painter->GetBrush()->SetColor(0.2, 0.4, 0.6);
  EXPECT_EQ(painter->GetMaximumDabsPerCall(), vtkIdType(1) << 22);
  vtkNew<MessageObserver> messages;
  messages->Watch(painter);
  // The default limit: five million dabs are refused before they are stored.
  vtkNew<vtkPoints> many;
  many->SetNumberOfPoints(5000000);
  for (vtkIdType i = 0; i < many->GetNumberOfPoints(); ++i)
  {
    many->SetPoint(i, 0.0, 0.0, 1.0);
  }
  const auto start = std::chrono::steady_clock::now();
  EXPECT_EQ(painter->Dabs(many), 0);
  const double seconds =
    std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  EXPECT_LT(seconds, 5.0);
  EXPECT_NE(messages->Errors.find("MaximumDabsPerCall (4194304)"), std::string::npos);
  vtkNew<vtkPolyData> asPolyData;
  asPolyData->SetPoints(many);
  messages->Clear();
  EXPECT_EQ(painter->Dabs(asPolyData), 0);
  EXPECT_NE(messages->Errors.find("MaximumDabsPerCall"), std::string::npos);

  // A set limit, reflections counted.
  painter->SetMaximumDabsPerCall(1000);
  vtkNew<vtkPoints> some;
  for (int i = 0; i < 600; ++i)
  {
    some->InsertNextPoint(0.5 + i * 1e-4, 0.0, 0.8);
  }
  EXPECT_GT(painter->Dabs(some), 0);
  painter->MirrorXOn();
  messages->Clear();
  EXPECT_EQ(painter->Dabs(some), 0);
  EXPECT_NE(messages->Errors.find("1200 dabs"), std::string::npos) << messages->Errors;
  EXPECT_NE(messages->Errors.find("MaximumDabsPerCall (1000)"), std::string::npos);
  EXPECT_EQ(painter->GetNumberOfUndoSteps(), 1);
}

//------------------------------------------------------------------------------
TEST(PainterRobust, ManyDabsReportProgressAndAbort)
{
  vtkNew<vtkPoints> points;
  for (int i = 0; i < 20000; ++i)
  {
    double p[3];
    OnSphere(0.001 * i, 0.37 * i, p);
    points->InsertNextPoint(p);
  }
  vtkIdType whole = 0;
  {
    vtkNew<vtkOFBPainter> painter;
    painter->SetOFB(SphereOFB(96));
    painter->GetBrush()->SetRadius(0.05);
    painter->GetBrush()->SetColor(0.2, 0.4, 0.6);
    std::vector<double> progress;
    vtkNew<vtkCallbackCommand> cb;
    cb->SetClientData(&progress);
    cb->SetCallback([](vtkObject*, unsigned long, void* cd, void* data)
      { static_cast<std::vector<double>*>(cd)->push_back(*static_cast<double*>(data)); });
    painter->AddObserver(vtkCommand::ProgressEvent, cb);
    whole = painter->Dabs(points);
    EXPECT_GT(whole, 0);
    EXPECT_GE(progress.size(), 10u);
    EXPECT_TRUE(std::is_sorted(progress.begin(), progress.end()));
    EXPECT_EQ(progress.back(), 1.0);
  }
  vtkNew<vtkOFBPainter> painter;
  vtkSmartPointer<vtkOFB> ofb = SphereOFB(96);
  painter->SetOFB(ofb);
  painter->GetBrush()->SetRadius(0.05);
  painter->GetBrush()->SetColor(0.2, 0.4, 0.6);
  ProgressAction abort(painter, [&]() { painter->AbortPaintOn(); });
  const vtkIdType aborted = painter->Dabs(points);
  EXPECT_TRUE(abort.Done);
  EXPECT_LT(aborted, whole / 2);
  // What was painted is one undo step, and the next call starts with AbortPaint off.
  EXPECT_EQ(painter->Undo(), aborted);
  EXPECT_EQ(painter->Dabs(points), whole);
  EXPECT_FALSE(painter->GetAbortPaint());
}

//------------------------------------------------------------------------------
TEST(PainterRobust, FiltersWithoutInputsOrCollaborators)
{
  // Without inputs: the pipeline's error, no crash, empty outputs.
  vtkNew<vtkOFBPaintFilter> paint;
  vtkNew<vtkOFBDecalPatch> decal;
  vtkNew<vtkOFBTextureProjector> projector;
  for (vtkAlgorithm* algorithm : std::vector<vtkAlgorithm*>{ paint, decal, projector })
  {
    vtkNew<MessageObserver> messages;
    messages->Watch(algorithm);
    messages->Watch(algorithm->GetExecutive());
    algorithm->Update();
    EXPECT_FALSE(messages->Errors.empty()) << algorithm->GetClassName();
  }
  // The paint filter without its brush or painter.
  vtkNew<vtkPoints> points;
  points->InsertNextPoint(0, 0, 1);
  vtkNew<vtkPolyData> strokes;
  strokes->SetPoints(points);
  for (int missing = 0; missing < 2; ++missing)
  {
    vtkNew<vtkOFBPaintFilter> filter;
    filter->SetInputData(SphereOFB(48));
    filter->SetStrokesData(strokes);
    if (missing == 0)
    {
      filter->SetBrush(nullptr);
    }
    else
    {
      filter->SetPainter(nullptr);
    }
    vtkNew<MessageObserver> messages;
    messages->Watch(filter);
    filter->Update();
    EXPECT_NE(messages->Errors.find("No brush or no painter"), std::string::npos);
    EXPECT_EQ(filter->GetOutput()->GetNumberOfSamples(), 0);
  }
}
