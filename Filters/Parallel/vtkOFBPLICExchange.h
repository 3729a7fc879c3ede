/**
 * @file   vtkOFBPLICExchange.h
 * @brief  vtkOFBPLIC's exchange of owned samples between processes (private)
 *
 * Each process sends to each other process the owned samples (ghost value 0) of its OFB
 * that lie within `radius` (world units) of the box of that process's owned samples, and
 * merges what it receives with its own owned samples into one OFB on the common frame:
 * the samples of each grid cell in order of depth, ties in the order of the processes,
 * as one process sampling the whole surface orders them. Around its owned samples, as
 * far as `radius`, that OFB holds the samples of one process; its own ghost samples are
 * left out (the owners' samples replace them). A negative radius sends every owned
 * sample to every process (an all-gather).
 *
 * Communication: one all-gather of 14 doubles a process (the boxes and frames), one of
 * 2 P counts a process (what each sends to each), then one message per pair of processes
 * that has samples for the other (pairs in the rounds of a round-robin tournament:
 * blocking sends cannot wait on each other). A process with no samples takes part.
 */
#ifndef vtkOFBPLICExchange_h
#define vtkOFBPLICExchange_h

#include "vtkOFB.h"
#include "vtkSmartPointer.h"

#include <string>
#include <vector>

class vtkMultiProcessController;

struct vtkOFBPLICExchange
{
  /// Own owned samples and the received ones, "vtkGhostType" 0 and 1; null on error.
  vtkSmartPointer<vtkOFB> Merged;
  /// For each input sample, its sample in Merged: an owned sample its own; a ghost
  /// sample the received one of its cell nearest in depth (within half a cell); or -1.
  std::vector<vtkIdType> InputToMerged;
  vtkIdType SentSamples = 0;
  vtkIdType ReceivedSamples = 0;
  vtkIdType SentBytes = 0;
  vtkIdType ReceivedBytes = 0;
  /// Why it failed (the same on every process where the cause is collective).
  std::string Problem;

  /**
   * Exchange the sample arrays `names` of `input` (null: no samples) with every process
   * of `controller`. Collective. False, with Problem set, when the processes' frames
   * differ or a received message does not match this process's arrays.
   */
  bool Run(vtkMultiProcessController* controller,
    vtkOFB* input,
    const std::vector<std::string>& names,
    double radius);
};

#endif
// VTK-HeaderTest-Exclude: vtkOFBPLICExchange.h
