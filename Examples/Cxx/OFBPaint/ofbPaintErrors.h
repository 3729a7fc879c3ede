// OFBPaint's file helpers (ofbPaintExport.cxx, ofbPaintDecal.cxx): the first error event
// of VTK objects, as a message for the user (the example applications' observer).
#ifndef ofbPaintErrors_h
#define ofbPaintErrors_h

#include "ofbExampleErrors.h"

namespace ofbpaint
{
using FirstError = ofbexample::FirstError;
}

#endif
