/**
 * @class   vtkOFBCPUSampler
 * @brief   The CPU backend of vtkOFBSampler: scan conversion with vtkSMPTools (private)
 *
 * Builds an OFB from a prepared surface in bands of grid rows
 * (vtkOFBSamplerBands.h describes the algorithm): the triangles are set up and
 * listed by band, pass 1 finds the spans and the number of samples of each band,
 * pass 2 fills each band on its own (samples, cell offsets, sort, attributes).
 * The memory is checked against the job's limit before each large allocation:
 * the cells and per-triangle buffers before the setup, the spans once counted,
 * the samples once counted.
 *
 * The setup, span and band buffers are kept from build to build (a rebuild
 * writes over memory it already has) until ReleaseBuffers().
 */

#ifndef vtkOFBCPUSampler_h
#define vtkOFBCPUSampler_h

#include "vtkOFBSamplerBackend.h"

#include <memory> // for std::unique_ptr

class vtkOFBSamplerBuffers;
namespace vtkofb
{
class BandBuilder;
}

class vtkOFBCPUSampler : public vtkOFBSamplerBackend
{
public:
  static vtkOFBCPUSampler* New();
  vtkTypeMacro(vtkOFBCPUSampler, vtkOFBSamplerBackend);

  Result Sample(Job& job) override;
  const char* GetBackendName() const override { return "CPU"; }
  double EstimateWorkBytes(vtkIdType points, vtkIdType triangles, double samples) const override;
  void ReleaseBuffers() override;

protected:
  vtkOFBCPUSampler();
  ~vtkOFBCPUSampler() override;

private:
  vtkOFBCPUSampler(const vtkOFBCPUSampler&) = delete;
  void operator=(const vtkOFBCPUSampler&) = delete;

  /// Refuse surfaces whose point or triangle ids do not fit in 32 bits.
  static bool CheckIdRange(Job& job);

  /**
   * Check the memory of the cells, the surface and the per-triangle buffers, then
   * set the output's frame (its cell offsets uninitialized: pass 2 writes them all).
   */
  bool SetUpFrame(Job& job) const;

  /**
   * Cut the bands, set up the triangles, list them by band, check the memory of
   * their spans and allocate them.
   */
  bool SetUpTriangles(vtkofb::BandBuilder& builder, Job& job) const;

  /// Pass 1: the spans and number of samples of every band.
  static void SpanBands(vtkofb::BandBuilder& builder);

  /**
   * The first sample of every band, the exact memory check and the samples
   * allocated (`samples` of them).
   */
  bool AllocateSamples(vtkofb::BandBuilder& builder, Job& job, vtkIdType& samples) const;

  /// Pass 2: every band filled, then the cell offsets closed and the arrays attached.
  void FillBands(vtkofb::BandBuilder& builder, Job& job, vtkIdType samples);

  std::unique_ptr<vtkOFBSamplerBuffers> Buffers;
};

#endif
