/**
 * @class   vtkOFBToPolyData
 * @brief   The samples of a vtkOFB as a point cloud
 *
 * vtkOFBToPolyData turns every sample of its input vtkOFB into a point at the
 * sample's position, carrying every sample array (colours, normals, the vector
 * field, interpolated arrays) as point data, so that any VTK tool or ParaView can
 * show or process the samples. With GenerateVertices (default on) each point gets
 * a vertex cell so that it renders. With GenerateGridAxis (default on) the output
 * also has an unsigned-char array "GridAxis" (0 = X, 1 = Y, 2 = Z), and with
 * GenerateCellIds (default off) a "CellIndex" array with the global cell of each
 * sample. An empty OFB gives an empty polydata.
 */

#ifndef vtkOFBToPolyData_h
#define vtkOFBToPolyData_h

#include "vtkOFBCoreModule.h" // for export macro
#include "vtkPolyDataAlgorithm.h"

class VTKOFBCORE_EXPORT vtkOFBToPolyData : public vtkPolyDataAlgorithm
{
public:
  static vtkOFBToPolyData* New();
  vtkTypeMacro(vtkOFBToPolyData, vtkPolyDataAlgorithm);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  ///@{
  /**
   * Add one vertex cell per point (default on).
   */
  vtkSetMacro(GenerateVertices, bool);
  vtkGetMacro(GenerateVertices, bool);
  vtkBooleanMacro(GenerateVertices, bool);
  ///@}

  ///@{
  /**
   * Add the "GridAxis" point array, the grid of each sample (default on).
   */
  vtkSetMacro(GenerateGridAxis, bool);
  vtkGetMacro(GenerateGridAxis, bool);
  vtkBooleanMacro(GenerateGridAxis, bool);
  ///@}

  ///@{
  /**
   * Add the "CellIndex" point array, the global cell of each sample (default off).
   */
  vtkSetMacro(GenerateCellIds, bool);
  vtkGetMacro(GenerateCellIds, bool);
  vtkBooleanMacro(GenerateCellIds, bool);
  ///@}

protected:
  vtkOFBToPolyData();
  ~vtkOFBToPolyData() override;

  int FillInputPortInformation(int port, vtkInformation* info) override;
  int RequestData(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;

  bool GenerateVertices;
  bool GenerateGridAxis;
  bool GenerateCellIds;

private:
  vtkOFBToPolyData(const vtkOFBToPolyData&) = delete;
  void operator=(const vtkOFBToPolyData&) = delete;
};

#endif
