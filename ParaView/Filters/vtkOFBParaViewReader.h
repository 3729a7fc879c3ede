/**
 * @class   vtkOFBParaViewReader
 * @brief   vtkOFBReader for ParaView: the whole OFB on every process, owned by the first
 *
 * ParaView's File > Open of an .ofb file (vtkOFBWriter's format). The reader reads the
 * whole file whatever the piece asked for, so that every process can probe, paint or
 * render any part of the surface with it. Piece 0 (the first process under MPI, the only
 * one otherwise) owns every sample; the other pieces get the same samples marked as
 * ghosts (a "vtkGhostType" sample array of vtkDataSetAttributes::DUPLICATEPOINT), so that
 * what sums or gathers owned samples (OFB LIC's statistics, the OFB writers under MPI)
 * counts each sample once. A file that vtkOFBReader refuses gives its error and an empty
 * OFB on every process.
 *
 * @sa vtkOFBReader vtkOFBParaViewWriter
 */

#ifndef vtkOFBParaViewReader_h
#define vtkOFBParaViewReader_h

#include "vtkOFBParaViewModule.h" // for export macro
#include "vtkOFBReader.h"

class VTKOFBPARAVIEW_EXPORT vtkOFBParaViewReader : public vtkOFBReader
{
public:
  static vtkOFBParaViewReader* New();
  vtkTypeMacro(vtkOFBParaViewReader, vtkOFBReader);
  void PrintSelf(ostream& os, vtkIndent indent) override;

protected:
  vtkOFBParaViewReader();
  ~vtkOFBParaViewReader() override;

  int RequestInformation(vtkInformation* request,
    vtkInformationVector** inInfo,
    vtkInformationVector* outInfo) override;
  int RequestData(vtkInformation* request,
    vtkInformationVector** inInfo,
    vtkInformationVector* outInfo) override;

private:
  vtkOFBParaViewReader(const vtkOFBParaViewReader&) = delete;
  void operator=(const vtkOFBParaViewReader&) = delete;
};

#endif
