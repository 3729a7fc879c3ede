/**
 * @file   ofbExampleDataFile.h
 * @brief  The files of ofbExampleData (private to it): one file as a data object
 */
#ifndef ofbExampleDataFile_h
#define ofbExampleDataFile_h

#include "ofbExampleData.h"

#include "vtkDataObject.h"
#include "vtkSmartPointer.h"

#include <string>

namespace ofbexample
{
/**
 * The data of the file at `path`, its format by content (else by extension; see
 * ofbExampleData.h): a VTK XML or legacy file at options' time step, a .pvd's parts at
 * options' time step as the blocks of a vtkMultiBlockDataSet (not inside another .pvd:
 * `inCollection`), or a mesh through ReadMeshChecked. `summary` says what was read; null
 * with `problem` the reason.
 */
vtkSmartPointer<vtkDataObject> ReadDataFile(const std::string& path,
  const DataOptions& options,
  bool inCollection,
  std::string& summary,
  std::string& problem);
}

#endif
