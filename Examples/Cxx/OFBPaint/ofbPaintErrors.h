// OFBPaint's file helpers (ofbPaintExport.cxx, ofbPaintDecal.cxx): the first error event
// of VTK objects, as a message for the user.
#ifndef ofbPaintErrors_h
#define ofbPaintErrors_h

#include "vtkCommand.h"

#include <string>

namespace ofbpaint
{
/// Keeps the first error event's text (VTK's message without its file and line).
class FirstError : public vtkCommand
{
public:
  static FirstError* New() { return new FirstError; }
  void Execute(vtkObject*, unsigned long, void* data) override
  {
    std::string text = data ? static_cast<const char*>(data) : "";
    const std::string::size_type start = text.find("): ");
    text = start == std::string::npos ? text : text.substr(start + 3);
    if (this->Text.empty())
    {
      this->Text = text.substr(0, text.find_last_not_of(" \n") + 1);
    }
  }
  std::string Text;
};
}

#endif
