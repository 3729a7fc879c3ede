// Private header of vtkOFBPolyDataMapper's source files: the header's names for the
// implementation's types, which it does not install.
#ifndef vtkOFBPolyDataMapperInternals_h
#define vtkOFBPolyDataMapperInternals_h

#include "vtkOFBPolyDataMapper.h"
#include "vtkOFBShaderStorage.h"

class vtkOFBPolyDataMapper::vtkStorage : public vtkOFBShaderStorage
{
};
struct vtkOFBPolyDataMapper::vtkSelection : public vtkOFBShaderStorage::Selection
{
};

#endif
