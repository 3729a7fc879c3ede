/**
 * @class   vtkOFBParaViewWriter
 * @brief   vtkOFBWriter for ParaView: one .ofb file from every process's piece
 *
 * ParaView's File > Save Data of an OFB (the output of OFB Sampler, LIC, Paint Strokes,
 * Particles or of an .ofb file) as vtkOFBWriter's format, which vtkOFBReader (in VTK or in
 * ParaView's File > Open) reads back. With one process it is vtkOFBWriter. Under MPI
 * (pvbatch, pvserver) every process's owned samples (vtkOFBSamplePack) go to the first
 * process, which merges them into one OFB on their common frame (the samples of each grid
 * cell in order of depth) and writes it as vtkOFBWriter does (replaced atomically; nothing
 * written on failure); every process then gets the same result (GetErrorCode()). Pieces
 * sampled on different frames, or an input that is not an OFB, are refused with an error
 * on every process and nothing written.
 *
 * @sa vtkOFBWriter vtkOFBParaViewReader vtkOFBSamplePack
 */

#ifndef vtkOFBParaViewWriter_h
#define vtkOFBParaViewWriter_h

#include "vtkOFBParaViewModule.h" // for export macro
#include "vtkOFBWriter.h"

class vtkMultiProcessController;

class VTKOFBPARAVIEW_EXPORT vtkOFBParaViewWriter : public vtkOFBWriter
{
public:
  static vtkOFBParaViewWriter* New();
  vtkTypeMacro(vtkOFBParaViewWriter, vtkOFBWriter);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  ///@{
  /**
   * The processes that write together (default: the global controller).
   */
  virtual void SetController(vtkMultiProcessController*);
  vtkGetObjectMacro(Controller, vtkMultiProcessController);
  ///@}

protected:
  vtkOFBParaViewWriter();
  ~vtkOFBParaViewWriter() override;

  /// Asks for this process's piece (of the Controller's processes) when there are more.
  vtkTypeBool ProcessRequest(vtkInformation* request,
    vtkInformationVector** inputVector,
    vtkInformationVector* outputVector) override;
  void WriteData() override;
  int FillInputPortInformation(int port, vtkInformation* info) override;

  vtkMultiProcessController* Controller;

private:
  vtkOFBParaViewWriter(const vtkOFBParaViewWriter&) = delete;
  void operator=(const vtkOFBParaViewWriter&) = delete;
};

#endif
