// Private header: the message about an array whose length does not match what it
// describes (points, cells, samples, seeds), shared by the filters that check it.
#ifndef vtkOFBArrayLength_h
#define vtkOFBArrayLength_h

#include "vtkAbstractArray.h"

#include <sstream>
#include <string>

/// "'name' has N tuples for M <what>".
inline std::string vtkOFBArrayLength(vtkAbstractArray* array, vtkIdType needed, const char* what)
{
  std::ostringstream os;
  os << "'" << (array->GetName() ? array->GetName() : "(unnamed)") << "' has "
     << array->GetNumberOfTuples() << " tuples for " << needed << " " << what;
  return os.str();
}

#endif
