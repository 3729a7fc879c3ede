// Private header of vtkOFBPainter and vtkOFBPaintFilter: the optional per-point arrays of
// dabs and strokes ("Radius", "Color", ...), checked before they are read.
#ifndef vtkOFBDabArrays_h
#define vtkOFBDabArrays_h

#include "vtkDataArray.h"
#include "vtkOFBInputChecks.h"
#include "vtkPointData.h"
#include "vtkPolyData.h"

#include <string>

/**
 * Finds the per-point arrays of `Data`. An array that is absent is fine (the brush's
 * setting applies); one that is present but has fewer components than asked for, or
 * fewer tuples than `Data` has points (reading it would run past its end), is bad input:
 * Get returns nullptr and Error says what is wrong (the first problem found).
 */
struct vtkOFBDabArrays
{
  vtkPolyData* Data;
  std::string Error;

  vtkDataArray* Get(const char* name, int components)
  {
    vtkDataArray* a = this->Data->GetPointData()->GetArray(name);
    if (!a)
    {
      return nullptr;
    }
    std::string error;
    if (!vtkOFBCheckArrayLength(a, this->Data->GetNumberOfPoints(), "points", error, components))
    {
      if (this->Error.empty())
      {
        this->Error = "the point array " + error + ".";
      }
      return nullptr;
    }
    return a;
  }
};

#endif
