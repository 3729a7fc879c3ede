/**
 * @file   ofbExampleErrors.h
 * @brief  The error events of VTK objects, as a message for the user
 *
 * The example applications observe vtkCommand::ErrorEvent on every reader, writer and
 * filter they run: a VTK error is then a failure of the application (a message and a
 * non-zero exit status), never only a line on the terminal.
 */
#ifndef ofbExampleErrors_h
#define ofbExampleErrors_h

#include "vtkCommand.h"

#include <string>

namespace ofbexample
{
/// Counts error events and keeps the first one's text (VTK's message without its file and
/// line).
class FirstError : public vtkCommand
{
public:
  static FirstError* New() { return new FirstError; }
  void Execute(vtkObject*, unsigned long, void* data) override
  {
    ++this->Count;
    std::string text = data ? static_cast<const char*>(data) : "";
    const std::string::size_type start = text.find("): ");
    text = start == std::string::npos ? text : text.substr(start + 3);
    if (this->Text.empty())
    {
      this->Text = text.substr(0, text.find_last_not_of(" \n") + 1);
    }
  }
  /// ": <first message>", or "" when there was none.
  std::string Suffix() const { return this->Text.empty() ? std::string() : ": " + this->Text; }
  int Count = 0;
  std::string Text;
};
}

#endif
