// Stroke files of the OFBPaint application: a small text format that replays painting on a
// vtkOFBPainter without a person at the mouse (OFBPaint --strokes FILE --image OUT.png).
//
// One command a line; '#' starts a comment; names are case-insensitive.
//
//   radius R                 brush radius in world units
//   radius-cells C           brush radius in OFB cells
//   color R G B [A]          brush colour, components in [0, 1]
//   strength S               brush strength in [0, 1]
//   falloff NAME             constant, linear, smooth, sphere, root, sharp, gaussian
//   blend NAME               mix, add, subtract, multiply, lighten, darken, erase, erasealpha
//   target NAME              color, normal, smear
//   mirror AXES              paint also at the reflections across the planes through the
//                            painter's MirrorOrigin (OFBPaint: the centre of the mesh's box):
//                            none, or letters of x, y and z (xz: across two planes)
//   spacing F                dab spacing of strokes, a fraction of the radius
//   smear-amount A           smear target: share of the carried colour, [0, 1]
//   bump-depth D             normal target: bump depth (negative: dents)
//   view AZ EL [ZOOM]        camera: azimuth and elevation (degrees) from the default view,
//                            zoom factor (pixel points depend on it: set it first)
//   stroke                   begin a stroke (one undo step); its points follow
//   X Y Z [PRESSURE]         a point in world coordinates (moved onto the surface: the
//                            closest sample; the dabs between two points follow the
//                            surface, see vtkOFBPainter::SetFollowSurface)
//   pixel PX PY [PRESSURE]   a point picked on the surface at pixel (PX, PY) of the image,
//                            from its top-left corner (skipped, with a note, off the surface)
//   end                      end the stroke (also ended by 'stroke' or the end of the file)
//   undo / redo              undo or redo the last stroke
//   decal PX PY              stamp the decal centred on the surface at pixel (PX, PY) (OFBPaint:
//                            --decal's image, or its badge, 4 brush radii wide; one undo step)
//
// A point outside a stroke paints a single dab there. Pressure (default 1) scales the
// strength (see vtkOFBBrush::PressureAffectsStrength).
//
// Limits: the file must be a regular file (not a directory, device or FIFO) of at most
// MaximumStrokeFileBytes bytes and MaximumStrokeFileLines lines, and a stroke may place at
// most MaximumStrokeDabs dabs (its path length over the dab step, Spacing x radius but at
// least an eighth of a cell); past a limit the replay stops with a message naming it.
#ifndef ofbPaintStrokes_h
#define ofbPaintStrokes_h

#include <functional>
#include <string>

class vtkOFBPainter;

namespace ofbpaint
{
/// The largest stroke file replayed: 16 MiB.
constexpr long long MaximumStrokeFileBytes = 16LL << 20;
/// The most lines of a stroke file: one million.
constexpr long long MaximumStrokeFileLines = 1000000;
/// The most dabs one stroke may place: 100,000 (a stroke across a whole model places a few
/// hundred).
constexpr double MaximumStrokeDabs = 100000.0;

/// What a replay did.
struct StrokeStatistics
{
  int Strokes = 0;
  int Points = 0;
  int SkippedPoints = 0; // pixel points off the surface
  long long SamplesChanged = 0;
};

/// Picks the surface point at pixel (x, y) from the image's top-left corner.
using PixelPicker = std::function<bool(double x, double y, double point[3])>;
/// Turns the camera: azimuth and elevation in degrees from the default view, zoom factor.
using ViewSetter = std::function<void(double azimuth, double elevation, double zoom)>;
/// Stamps the decal centred at a surface point; the samples changed, or -1 (`message` set).
using DecalStamp = std::function<long long(const double point[3], std::string& message)>;

/// Replay the stroke file `path` on `painter` (which has an OFB and a brush). Returns
/// false with `error` set to "FILE:LINE: message" on a bad line, "FILE: message" on an
/// unreadable file or one over the limits above; what was painted before stays painted.
bool ReplayStrokes(const std::string& path,
  vtkOFBPainter* painter,
  const PixelPicker& pick,
  const ViewSetter& view,
  StrokeStatistics& statistics,
  std::string& error,
  const DecalStamp& stamp = nullptr);
}

#endif
