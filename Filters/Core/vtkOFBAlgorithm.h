/**
 * @class   vtkOFBAlgorithm
 * @brief   Superclass for algorithms that produce a vtkOFB
 *
 * vtkOFBAlgorithm is to vtkOFB what vtkPolyDataAlgorithm is to vtkPolyData: it
 * creates a vtkOFB on every output port and routes the pipeline requests to
 * RequestInformation, RequestUpdateExtent and RequestData. By default it has one
 * input port accepting a vtkPolyData and one output port; subclasses change that
 * with SetNumberOfInputPorts and FillInputPortInformation.
 */

#ifndef vtkOFBAlgorithm_h
#define vtkOFBAlgorithm_h

#include "vtkAlgorithm.h"
#include "vtkOFBCoreModule.h" // for export macro

class vtkOFB;

class VTKOFBCORE_EXPORT vtkOFBAlgorithm : public vtkAlgorithm
{
public:
  static vtkOFBAlgorithm* New();
  vtkTypeMacro(vtkOFBAlgorithm, vtkAlgorithm);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  ///@{
  /**
   * The output OFB of a port.
   */
  vtkOFB* GetOutput();
  vtkOFB* GetOutput(int port);
  ///@}

  ///@{
  /**
   * Connect a data object directly as the input of port 0 (or of `port`), as
   * vtkPolyDataAlgorithm::SetInputData. Both overloads are declared here so that a
   * subclass (and Python) keeps the one taking a port.
   */
  void SetInputData(vtkDataObject* input);
  void SetInputData(int port, vtkDataObject* input);
  ///@}

  /**
   * Dispatch the pipeline passes.
   */
  vtkTypeBool ProcessRequest(vtkInformation* request,
    vtkInformationVector** inInfo,
    vtkInformationVector* outInfo) override;

protected:
  vtkOFBAlgorithm();
  ~vtkOFBAlgorithm() override;

  virtual int RequestDataObject(vtkInformation*, vtkInformationVector**, vtkInformationVector*);
  virtual int RequestInformation(vtkInformation*, vtkInformationVector**, vtkInformationVector*);
  virtual int RequestUpdateExtent(vtkInformation*, vtkInformationVector**, vtkInformationVector*);
  virtual int RequestData(vtkInformation*, vtkInformationVector**, vtkInformationVector*);

  int FillOutputPortInformation(int port, vtkInformation* info) override;
  int FillInputPortInformation(int port, vtkInformation* info) override;

private:
  vtkOFBAlgorithm(const vtkOFBAlgorithm&) = delete;
  void operator=(const vtkOFBAlgorithm&) = delete;
};

#endif
