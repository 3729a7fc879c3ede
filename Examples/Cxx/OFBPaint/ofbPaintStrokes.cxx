#include "ofbPaintStrokes.h"

#include "vtkDoubleArray.h"
#include "vtkMath.h"
#include "vtkNew.h"
#include "vtkOFB.h"
#include "vtkOFBBrush.h"
#include "vtkOFBPainter.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"

#include <sys/stat.h>

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <cmath>
#include <cstring>
#include <fstream>
#include <iostream>
#include <iterator>
#include <sstream>
#include <vector>

namespace ofbpaint
{
namespace
{
std::string Lower(std::string text)
{
  std::transform(text.begin(),
    text.end(),
    text.begin(),
    [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return text;
}

// The index i in [0, count) whose name(i), lower-cased without spaces, equals `word`; -1.
int FindName(const std::string& word, int count, const char* (*name)(int))
{
  for (int i = 0; i < count; ++i)
  {
    std::string candidate = Lower(name(i) ? name(i) : "");
    candidate.erase(std::remove(candidate.begin(), candidate.end(), ' '), candidate.end());
    if (candidate == Lower(word))
    {
      return i;
    }
  }
  return -1;
}

// The numbers after the command word; false if any word is not a finite number.
bool ParseNumbers(std::istringstream& words, std::vector<double>& numbers)
{
  std::string word;
  while (words >> word)
  {
    char* end = nullptr;
    const double v = std::strtod(word.c_str(), &end);
    if (*end || !std::isfinite(v))
    {
      return false;
    }
    numbers.push_back(v);
  }
  return true;
}

// One replay: the painter, the callbacks and the state of the open stroke.
class Replay
{
public:
  Replay(vtkOFBPainter* painter,
    const PixelPicker& pick,
    const ViewSetter& view,
    const DecalStamp& stamp,
    StrokeStatistics& statistics)
    : Painter(painter)
    , Brush(painter->GetBrush())
    , Pick(pick)
    , View(view)
    , Stamp(stamp)
    , Statistics(statistics)
  {
  }

  // Run one line; false with `error` set on a bad one.
  bool Line(const std::string& line, std::string& error);

  void EndStroke()
  {
    if (this->InStroke)
    {
      this->Painter->EndStroke();
      this->InStroke = false;
    }
    this->StrokeDabs = 0.0;
    this->HasLastPoint = false;
  }

private:
  bool Setting(const std::string& command, const std::vector<double>& v, std::string& error);
  bool Named(const std::string& command, const std::string& name, std::string& error);
  bool Point(const double p[3], double pressure, std::string& error);
  /// Count the dabs of the stroke's segment to p; false past MaximumStrokeDabs.
  bool CountDabs(const double p[3], double pressure, std::string& error);
  /// `decal PX PY` at surface point p (`wellFormed`: two values were given).
  bool Decal(const double p[3], bool wellFormed, std::string& error);

  vtkOFBPainter* Painter;
  vtkOFBBrush* Brush;
  const PixelPicker& Pick;
  const ViewSetter& View;
  const DecalStamp& Stamp;
  StrokeStatistics& Statistics;
  bool InStroke = false;
  double StrokeDabs = 0.0; // the open stroke's dabs so far
  bool HasLastPoint = false;
  double LastPoint[3] = { 0.0, 0.0, 0.0 };
  double LastPressure = 1.0;
};

bool Replay::CountDabs(const double p[3], double pressure, std::string& error)
{
  // The painter's dab step (vtkOFBPainter): Spacing x the radius at the lower pressure of
  // the segment's ends, but at least an eighth of a cell.
  const double cell = this->Painter->GetOFB()->GetCellSize();
  const double radius = this->Brush->GetRadius() *
    (this->Brush->GetPressureAffectsRadius() ? std::min(pressure, this->LastPressure) : 1.0);
  const double step = std::max({ this->Painter->GetSpacing() * radius, 0.125 * cell, 1e-300 });
  const double length =
    this->HasLastPoint ? std::sqrt(vtkMath::Distance2BetweenPoints(p, this->LastPoint)) : 0.0;
  this->StrokeDabs += 1.0 + length / step;
  std::copy(p, p + 3, this->LastPoint);
  this->LastPressure = pressure;
  this->HasLastPoint = true;
  if (this->StrokeDabs > MaximumStrokeDabs)
  {
    std::ostringstream text;
    text << "the stroke would place more than " << MaximumStrokeDabs
         << " dabs, the limit of a stroke (radius " << this->Brush->GetRadius() << ", spacing "
         << this->Painter->GetSpacing() << ")";
    error = text.str();
    return false;
  }
  return true;
}

bool Replay::Decal(const double p[3], bool wellFormed, std::string& error)
{
  if (!wellFormed)
  {
    error = "a decal is 'decal PX PY'";
    return false;
  }
  if (!this->Stamp)
  {
    error = "no decal to stamp here";
    return false;
  }
  this->EndStroke();
  const long long changed = this->Stamp(p, error);
  if (changed < 0)
  {
    return false;
  }
  this->Statistics.SamplesChanged += changed;
  return true;
}

bool Replay::Point(const double p[3], double pressure, std::string& error)
{
  ++this->Statistics.Points;
  if (this->InStroke)
  {
    if (!this->CountDabs(p, pressure, error))
    {
      return false;
    }
    this->Statistics.SamplesChanged += this->Painter->StrokeTo(p, pressure);
    return true;
  }
  // A single dab, with its pressure as the painter's per-dab "Pressure" array.
  vtkNew<vtkPoints> points;
  points->InsertNextPoint(p);
  vtkNew<vtkDoubleArray> pressures;
  pressures->SetName("Pressure");
  pressures->InsertNextValue(pressure);
  vtkNew<vtkPolyData> dab;
  dab->SetPoints(points);
  dab->GetPointData()->AddArray(pressures);
  this->Statistics.SamplesChanged += this->Painter->Dabs(dab);
  return true;
}

bool Replay::Named(const std::string& command, const std::string& name, std::string& error)
{
  int value = -1;
  if (command == "falloff")
  {
    value = FindName(name, vtkOFBBrush::FALLOFF_CUSTOM, vtkOFBBrush::GetFalloffAsString);
    if (value >= 0)
    {
      this->Brush->SetFalloff(value);
    }
  }
  else if (command == "blend")
  {
    value = FindName(name, vtkOFBBrush::NUMBER_OF_BLEND_MODES, vtkOFBBrush::GetBlendModeAsString);
    if (value >= 0)
    {
      this->Brush->SetBlendMode(value);
    }
  }
  else if (command == "target")
  {
    value = FindName(name, vtkOFBBrush::NUMBER_OF_TARGETS, vtkOFBBrush::GetTargetAsString);
    if (value >= 0)
    {
      this->Brush->SetTarget(value);
    }
  }
  else if (command == "mirror")
  {
    const std::string axes = Lower(name);
    if (axes == "none" || axes.find_first_not_of("xyz") == std::string::npos)
    {
      value = 0;
      this->Painter->SetMirrorX(axes.find('x') != std::string::npos);
      this->Painter->SetMirrorY(axes.find('y') != std::string::npos);
      this->Painter->SetMirrorZ(axes.find('z') != std::string::npos);
    }
  }
  if (value < 0)
  {
    error = "unknown " + command + " '" + name + "'";
    return false;
  }
  return true;
}

bool Replay::Setting(const std::string& command, const std::vector<double>& v, std::string& error)
{
  const size_t n = v.size();
  const bool one = n == 1;
  if (command == "radius" && one && v[0] > 0.0)
  {
    this->Brush->SetRadius(v[0]);
  }
  else if (command == "radius-cells" && one && v[0] > 0.0)
  {
    this->Brush->SetRadiusInCells(v[0], this->Painter->GetOFB());
  }
  else if (command == "color" && (n == 3 || n == 4))
  {
    this->Brush->SetColor(v[0], v[1], v[2], n == 4 ? v[3] : this->Brush->GetOpacity());
  }
  else if (command == "strength" && one)
  {
    this->Brush->SetStrength(v[0]);
  }
  else if (command == "spacing" && one)
  {
    this->Painter->SetSpacing(v[0]);
  }
  else if (command == "smear-amount" && one)
  {
    this->Brush->SetSmearAmount(v[0]);
  }
  else if (command == "bump-depth" && one)
  {
    this->Brush->SetBumpDepth(v[0]);
  }
  else if (command == "view" && (n == 2 || n == 3) && (n == 2 || v[2] > 0.0))
  {
    this->EndStroke();
    this->View(v[0], v[1], n == 3 ? v[2] : 1.0);
  }
  else
  {
    const char* settings[] = {
      "radius", "radius-cells", "color", "strength", "spacing", "smear-amount", "bump-depth", "view"
    };
    const bool known =
      std::find(std::begin(settings), std::end(settings), command) != std::end(settings);
    error = known ? "bad values for '" + command + "'" : "unknown command '" + command + "'";
    return false;
  }
  return true;
}

bool Replay::Line(const std::string& text, std::string& error)
{
  std::istringstream words(text.substr(0, text.find('#')));
  std::string command;
  if (!(words >> command))
  {
    return true; // blank or comment
  }
  command = Lower(command);
  if (command == "stroke" || command == "end" || command == "undo" || command == "redo")
  {
    this->EndStroke();
    if (command == "stroke")
    {
      this->Painter->BeginStroke();
      this->InStroke = true;
      ++this->Statistics.Strokes;
    }
    else if (command == "undo")
    {
      this->Painter->Undo();
    }
    else if (command == "redo")
    {
      this->Painter->Redo();
    }
    return true;
  }
  if (command == "falloff" || command == "blend" || command == "target" || command == "mirror")
  {
    std::string name;
    return (words >> name) ? this->Named(command, name, error)
                           : (error = "'" + command + "' needs a name", false);
  }
  std::vector<double> v;
  const bool decal = command == "decal";
  const bool pixel = command == "pixel" || decal;
  const bool point = !pixel &&
    (std::isdigit(static_cast<unsigned char>(command[0])) || command[0] == '-' ||
      command[0] == '+' || command[0] == '.');
  if (point)
  {
    words.clear();
    words.str(text.substr(0, text.find('#')));
  }
  if (!ParseNumbers(words, v))
  {
    error = "'" + command + "': values must be finite numbers";
    return false;
  }
  if (point || pixel)
  {
    const size_t coordinates = pixel ? 2 : 3;
    if (v.size() != coordinates && v.size() != coordinates + 1)
    {
      error = pixel ? "a pixel point is 'pixel PX PY [PRESSURE]'" : "a point is 'X Y Z [PRESSURE]'";
      return false;
    }
    const double pressure = v.size() > coordinates ? v[coordinates] : 1.0;
    double p[3] = { v[0], v[1], pixel ? 0.0 : v[2] };
    if (pixel && !this->Pick(v[0], v[1], p))
    {
      ++this->Statistics.SkippedPoints;
      return true;
    }
    if (decal)
    {
      return this->Decal(p, v.size() == 2, error);
    }
    return this->Point(p, std::min(1.0, std::max(0.0, pressure)), error);
  }
  return this->Setting(command, v, error);
}
}

namespace
{
/// A regular file (not a directory, device or FIFO: checked before opening it, which a
/// FIFO would block) within MaximumStrokeFileBytes.
bool CheckStrokeFile(const std::string& path, std::string& problem)
{
  struct stat info;
  if (stat(path.c_str(), &info) != 0)
  {
    problem = "cannot open the stroke file: " + std::string(std::strerror(errno));
    return false;
  }
  if (!S_ISREG(info.st_mode))
  {
    problem = S_ISDIR(info.st_mode) ? "a directory, not a stroke file"
                                    : "not a regular file (a device or FIFO), not a stroke file";
    return false;
  }
  if (info.st_size > MaximumStrokeFileBytes)
  {
    problem = "larger than the limit of " + std::to_string(MaximumStrokeFileBytes) +
      " bytes of a stroke file";
    return false;
  }
  return true;
}
}

bool ReplayStrokes(const std::string& path,
  vtkOFBPainter* painter,
  const PixelPicker& pick,
  const ViewSetter& view,
  StrokeStatistics& statistics,
  std::string& error,
  const DecalStamp& stamp)
{
  std::string problem;
  if (!CheckStrokeFile(path, problem))
  {
    error = path + ": " + problem;
    return false;
  }
  std::ifstream in(path);
  if (!in)
  {
    error = path + ": cannot open the stroke file";
    return false;
  }
  if (!painter || !painter->GetOFB() || !painter->GetBrush())
  {
    error = path + ": no painter, OFB or brush to replay on";
    return false;
  }
  Replay replay(painter, pick, view, stamp, statistics);
  std::string line;
  long long bytes = 0;
  for (long long number = 1; std::getline(in, line); ++number)
  {
    std::string message;
    bytes += static_cast<long long>(line.size()) + 1;
    if (number > MaximumStrokeFileLines || bytes > MaximumStrokeFileBytes)
    {
      replay.EndStroke();
      error = path + ": longer than the limit of " + std::to_string(MaximumStrokeFileLines) +
        " lines and " + std::to_string(MaximumStrokeFileBytes) + " bytes of a stroke file";
      return false;
    }
    if (!replay.Line(line, message))
    {
      replay.EndStroke();
      error = path + ":" + std::to_string(number) + ": " + message;
      return false;
    }
  }
  replay.EndStroke();
  return true;
}
}
