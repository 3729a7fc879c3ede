// A time-aware test source: a sphere carrying the rotation field v(x, t) = w(t) x x,
// whose axis w(t) = Omega (sin(Alpha t), 0, cos(Alpha t)) turns with time, at the
// time steps t_k = k * Step, k = 0 .. NumberOfSteps - 1 (as a reader of a time
// series reports them: TIME_STEPS and TIME_RANGE).
#ifndef vtkOFBTurningRotationSource_h
#define vtkOFBTurningRotationSource_h

#include "vtkFloatArray.h"
#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkPolyDataAlgorithm.h"
#include "vtkSmartPointer.h"
#include "vtkStreamingDemandDrivenPipeline.h"

#include <algorithm>
#include <cmath>
#include <vector>

namespace vtkofbtest
{
class TurningRotationSource : public vtkPolyDataAlgorithm
{
public:
  static TurningRotationSource* New()
  {
    auto* source = new TurningRotationSource;
    source->InitializeObjectBase();
    return source;
  }
  vtkTypeMacro(TurningRotationSource, vtkPolyDataAlgorithm);

  /// The mesh (its points are copied into new arrays at every step, as a reader does).
  vtkSmartPointer<vtkPolyData> Mesh;
  double Omega = 1.0; // angular speed (rad per unit time)
  double Alpha = 1.0; // turning rate of the axis (rad per unit time)
  double Step = 0.1;  // time between steps
  int NumberOfSteps = 21;
  int Executions = 0;                 // RequestData calls
  std::vector<double> RequestedTimes; // UPDATE_TIME_STEP of each call

  /// The axis w(t).
  void Axis(double t, double w[3]) const
  {
    w[0] = this->Omega * std::sin(this->Alpha * t);
    w[1] = 0.0;
    w[2] = this->Omega * std::cos(this->Alpha * t);
  }

  /// v(x, t) = w(t) x x.
  void Velocity(const double x[3], double t, double v[3]) const
  {
    double w[3];
    this->Axis(t, w);
    v[0] = w[1] * x[2] - w[2] * x[1];
    v[1] = w[2] * x[0] - w[0] * x[2];
    v[2] = w[0] * x[1] - w[1] * x[0];
  }

  /**
   * The exact pathline: x advanced from t0 to t1 by RK4 in `steps` steps (the
   * reference, far finer than any advector step).
   */
  void Advance(double x[3], double t0, double t1, int steps = 20000) const
  {
    const double h = (t1 - t0) / steps;
    for (int i = 0; i < steps; ++i)
    {
      const double t = t0 + i * h;
      double k1[3], k2[3], k3[3], k4[3], y[3];
      this->Velocity(x, t, k1);
      for (int c = 0; c < 3; ++c)
      {
        y[c] = x[c] + 0.5 * h * k1[c];
      }
      this->Velocity(y, t + 0.5 * h, k2);
      for (int c = 0; c < 3; ++c)
      {
        y[c] = x[c] + 0.5 * h * k2[c];
      }
      this->Velocity(y, t + 0.5 * h, k3);
      for (int c = 0; c < 3; ++c)
      {
        y[c] = x[c] + h * k3[c];
      }
      this->Velocity(y, t + h, k4);
      for (int c = 0; c < 3; ++c)
      {
        x[c] += h / 6.0 * (k1[c] + 2.0 * k2[c] + 2.0 * k3[c] + k4[c]);
      }
    }
  }

protected:
  TurningRotationSource() { this->SetNumberOfInputPorts(0); }

  int RequestInformation(vtkInformation*,
    vtkInformationVector**,
    vtkInformationVector* out) override
  {
    vtkInformation* info = out->GetInformationObject(0);
    std::vector<double> steps(this->NumberOfSteps);
    for (int k = 0; k < this->NumberOfSteps; ++k)
    {
      steps[k] = k * this->Step;
    }
    info->Set(vtkStreamingDemandDrivenPipeline::TIME_STEPS(), steps.data(), this->NumberOfSteps);
    const double range[2] = { steps.front(), steps.back() };
    info->Set(vtkStreamingDemandDrivenPipeline::TIME_RANGE(), range, 2);
    return 1;
  }

  int RequestData(vtkInformation*, vtkInformationVector**, vtkInformationVector* out) override
  {
    vtkInformation* info = out->GetInformationObject(0);
    double t = 0.0;
    if (info->Has(vtkStreamingDemandDrivenPipeline::UPDATE_TIME_STEP()))
    {
      t = info->Get(vtkStreamingDemandDrivenPipeline::UPDATE_TIME_STEP());
    }
    // The step at or below t, clamped to the range (as VTK's readers do).
    const int k = std::max(
      0, std::min(this->NumberOfSteps - 1, static_cast<int>(std::floor(t / this->Step + 1e-9))));
    const double tk = k * this->Step;
    ++this->Executions;
    this->RequestedTimes.push_back(t);
    vtkPolyData* output = vtkPolyData::GetData(info);
    output->ShallowCopy(this->Mesh);
    auto points = vtkSmartPointer<vtkPoints>::New();
    points->DeepCopy(this->Mesh->GetPoints());
    output->SetPoints(points);
    output->GetPointData()->Initialize();
    auto velocity = vtkSmartPointer<vtkFloatArray>::New();
    velocity->SetName("Velocity");
    velocity->SetNumberOfComponents(3);
    velocity->SetNumberOfTuples(points->GetNumberOfPoints());
    for (vtkIdType i = 0; i < points->GetNumberOfPoints(); ++i)
    {
      double x[3], v[3];
      points->GetPoint(i, x);
      this->Velocity(x, tk, v);
      velocity->SetTuple(i, v);
    }
    output->GetPointData()->SetVectors(velocity);
    output->GetInformation()->Set(vtkDataObject::DATA_TIME_STEP(), tk);
    return 1;
  }

private:
  TurningRotationSource(const TurningRotationSource&) = delete;
  void operator=(const TurningRotationSource&) = delete;
};
}

#endif
