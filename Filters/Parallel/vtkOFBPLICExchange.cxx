#include "vtkOFBPLICExchange.h"

#include "vtkCommunicator.h"
#include "vtkDataArray.h"
#include "vtkDataSetAttributes.h"
#include "vtkFloatArray.h"
#include "vtkMultiProcessController.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkTypeUInt32Array.h"
#include "vtkUnsignedCharArray.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <limits>
#include <numeric>

namespace
{
// A process's row of the first all-gather: the box of its owned samples (6), whether it
// has any (1), its frame: origin (3), cell size (1), dimensions (3).
constexpr int RowValues = 14;
constexpr int ExchangeTag = 41719;

/// The sample arrays to exchange, with the bytes of a sample's record: cell (4 bytes),
/// depth (4), then a tuple of each array as it is stored.
struct Arrays
{
  std::vector<vtkDataArray*> List;
  std::vector<size_t> TupleBytes;
  size_t RecordBytes = 8;
  bool Valid = true;

  Arrays(vtkOFB* ofb, const std::vector<std::string>& names)
  {
    const vtkIdType n = ofb ? ofb->GetNumberOfSamples() : 0;
    for (const std::string& name : names)
    {
      vtkDataArray* array = ofb ? ofb->GetSampleData()->GetArray(name.c_str()) : nullptr;
      if (!array || array->GetNumberOfTuples() < n || !array->HasStandardMemoryLayout())
      {
        this->Valid = false;
        continue;
      }
      this->List.push_back(array);
      const size_t bytes =
        static_cast<size_t>(array->GetNumberOfComponents()) * array->GetDataTypeSize();
      this->TupleBytes.push_back(bytes);
      this->RecordBytes += bytes;
    }
  }

  const unsigned char* Tuple(size_t a, vtkIdType i) const
  {
    return static_cast<const unsigned char*>(this->List[a]->GetVoidPointer(0)) +
      static_cast<size_t>(i) * this->TupleBytes[a];
  }
};

/// The partner of `rank` in round `round` (0 .. size + size % 2 - 2) of a round-robin
/// tournament of `size` processes: every pair meets in exactly one round; `rank` itself
/// where it sits the round out.
int Partner(int rank, int round, int size)
{
  const int m = size + (size % 2);
  int partner = 0;
  if (rank == m - 1)
  {
    partner = round;
  }
  else if (rank == round)
  {
    partner = m - 1;
  }
  else
  {
    partner = ((2 * round - rank) % (m - 1) + (m - 1)) % (m - 1);
  }
  return partner < size ? partner : rank;
}

/// A sample of the merged OFB: its cell, depth, the process it comes from, its index there.
struct Entry
{
  vtkTypeUInt32 Cell;
  float Depth;
  int Source;
  vtkIdType Index;
};

/// What one exchange works on.
struct Work
{
  vtkMultiProcessController* Controller = nullptr;
  int Size = 1;
  int Me = 0;
  vtkOFB* Input = nullptr;
  vtkIdType N = 0;
  const unsigned char* Ghosts = nullptr;
  const vtkTypeUInt32* Cells = nullptr;
  const float* Depths = nullptr;
  std::vector<vtkIdType> Owned;
  std::vector<double> Positions; // of the owned samples
  double Row[RowValues];
  std::vector<double> Rows;                     // every process's Row
  std::vector<std::vector<vtkIdType>> Selected; // the owned samples for each process
  std::vector<vtkIdType> Counts;                // samples, bytes for each process
  std::vector<vtkIdType> Table;                 // every process's Counts
  std::vector<std::vector<unsigned char>> Received;
  std::vector<Entry> Entries;

  /// What process `from` sends to process `to`: samples (0) or bytes (1).
  vtkIdType Sent(int from, int to, int what) const
  {
    return this->Table[2 * static_cast<size_t>(this->Size) * from + 2 * to + what];
  }
};

/// The owned samples, their box and the frame of every process (one all-gather).
void GatherBoxes(Work& w)
{
  std::fill(w.Row, w.Row + RowValues, 0.0);
  for (int a = 0; a < 3; ++a)
  {
    w.Row[2 * a] = std::numeric_limits<double>::max();
    w.Row[2 * a + 1] = std::numeric_limits<double>::lowest();
  }
  for (vtkIdType i = 0; i < w.N; ++i)
  {
    double x[3];
    if ((!w.Ghosts || w.Ghosts[i] == 0) && w.Input->GetSamplePosition(i, x))
    {
      w.Owned.push_back(i);
      w.Positions.insert(w.Positions.end(), x, x + 3);
      for (int a = 0; a < 3; ++a)
      {
        w.Row[2 * a] = std::min(w.Row[2 * a], x[a]);
        w.Row[2 * a + 1] = std::max(w.Row[2 * a + 1], x[a]);
      }
    }
  }
  w.Row[6] = w.Owned.empty() ? 0.0 : 1.0;
  if (w.Input && w.Input->GetCellSize() > 0.0)
  {
    for (int a = 0; a < 3; ++a)
    {
      w.Row[7 + a] = w.Input->GetOrigin()[a];
      w.Row[11 + a] = static_cast<double>(w.Input->GetDimensions()[a]);
    }
    w.Row[10] = w.Input->GetCellSize();
  }
  w.Rows.resize(static_cast<size_t>(RowValues) * w.Size);
  w.Controller->AllGather(w.Row, w.Rows.data(), RowValues);
}

/// The frame of every process that has one (origin, cell size, dimensions): null where
/// none has, or (with `problem`) where they differ.
const double* CommonFrame(const Work& w, std::string& problem)
{
  const double* frame = nullptr;
  for (int r = 0; r < w.Size; ++r)
  {
    const double* other = w.Rows.data() + RowValues * r + 7;
    if (!(other[3] > 0.0))
    {
      continue;
    }
    if (frame && !std::equal(other, other + 7, frame))
    {
      problem = "the processes' OFBs have different frames (sample them on one frame: "
                "vtkOFBPSampler)";
      return nullptr;
    }
    frame = frame ? frame : other;
  }
  return frame;
}

/// For each other process, the owned samples within `radius` of its owned samples' box
/// (every owned sample where `radius` is negative); then what every process sends to
/// every other (one all-gather of 2 P counts).
void Select(Work& w, const Arrays& arrays, double radius)
{
  w.Selected.assign(w.Size, {});
  for (int r = 0; r < w.Size && arrays.Valid && !w.Owned.empty(); ++r)
  {
    const double* box = w.Rows.data() + RowValues * r;
    if (r == w.Me || box[6] == 0.0)
    {
      continue;
    }
    double lo[3], hi[3];
    bool meets = true;
    for (int a = 0; a < 3; ++a)
    {
      lo[a] = radius < 0.0 ? std::numeric_limits<double>::lowest() : box[2 * a] - radius;
      hi[a] = radius < 0.0 ? std::numeric_limits<double>::max() : box[2 * a + 1] + radius;
      meets = meets && w.Row[2 * a] <= hi[a] && w.Row[2 * a + 1] >= lo[a];
    }
    for (size_t k = 0; meets && k < w.Owned.size(); ++k)
    {
      const double* x = w.Positions.data() + 3 * k;
      if (x[0] >= lo[0] && x[0] <= hi[0] && x[1] >= lo[1] && x[1] <= hi[1] && x[2] >= lo[2] &&
        x[2] <= hi[2])
      {
        w.Selected[r].push_back(w.Owned[k]);
      }
    }
  }
  w.Counts.assign(2 * static_cast<size_t>(w.Size), 0);
  for (int r = 0; r < w.Size; ++r)
  {
    w.Counts[2 * r] = static_cast<vtkIdType>(w.Selected[r].size());
    w.Counts[2 * r + 1] = w.Counts[2 * r] * static_cast<vtkIdType>(arrays.RecordBytes);
  }
  w.Table.resize(2 * static_cast<size_t>(w.Size) * w.Size);
  w.Controller->AllGather(w.Counts.data(), w.Table.data(), 2 * w.Size);
}

/// One message each way per pair of processes that has samples for the other, in the
/// rounds of a round-robin tournament (the lower process of a pair sends first).
void Transfer(Work& w, const Arrays& arrays, vtkOFBPLICExchange& result)
{
  w.Received.assign(w.Size, {});
  for (int round = 0; round < w.Size + (w.Size % 2) - 1; ++round)
  {
    const int p = Partner(w.Me, round, w.Size);
    if (p == w.Me)
    {
      continue;
    }
    std::vector<unsigned char> message(static_cast<size_t>(w.Counts[2 * p + 1]));
    unsigned char* out = message.data();
    for (vtkIdType i : w.Selected[p])
    {
      std::memcpy(out, w.Cells + i, 4);
      std::memcpy(out + 4, w.Depths + i, 4);
      out += 8;
      for (size_t a = 0; a < arrays.List.size(); ++a)
      {
        std::memcpy(out, arrays.Tuple(a, i), arrays.TupleBytes[a]);
        out += arrays.TupleBytes[a];
      }
    }
    const vtkIdType expected = w.Sent(p, w.Me, 1);
    w.Received[p].resize(static_cast<size_t>(expected));
    for (int step = 0; step < 2; ++step)
    {
      if ((step == 0) == (w.Me < p))
      {
        if (!message.empty())
        {
          w.Controller->Send(
            message.data(), static_cast<vtkIdType>(message.size()), p, ExchangeTag);
        }
      }
      else if (expected > 0)
      {
        w.Controller->Receive(w.Received[p].data(), expected, p, ExchangeTag);
      }
    }
    result.SentSamples += w.Counts[2 * p];
    result.SentBytes += w.Counts[2 * p + 1];
    result.ReceivedBytes += expected;
  }
}

/// Own owned samples and the received ones, in the order of the processes, then sorted
/// as one process orders them: by cell, then depth.
void Collect(Work& w, const Arrays& arrays, vtkOFBPLICExchange& result)
{
  for (int r = 0; r < w.Size; ++r)
  {
    if (r == w.Me)
    {
      for (vtkIdType i : w.Owned)
      {
        w.Entries.push_back({ w.Cells[i], w.Depths[i], w.Me, i });
      }
      continue;
    }
    const vtkIdType count = w.Sent(r, w.Me, 0);
    if (count == 0)
    {
      continue;
    }
    if (count * static_cast<vtkIdType>(arrays.RecordBytes) !=
      static_cast<vtkIdType>(w.Received[r].size()))
    {
      result.Problem =
        "process " + std::to_string(r) + "'s samples do not have this process's sample arrays";
      continue;
    }
    for (vtkIdType k = 0; k < count; ++k)
    {
      const unsigned char* record = w.Received[r].data() + k * arrays.RecordBytes;
      Entry e{ 0, 0.0f, r, k };
      std::memcpy(&e.Cell, record, 4);
      std::memcpy(&e.Depth, record + 4, 4);
      w.Entries.push_back(e);
    }
    result.ReceivedSamples += count;
  }
  std::stable_sort(w.Entries.begin(),
    w.Entries.end(),
    [](const Entry& a, const Entry& b)
    { return a.Cell != b.Cell ? a.Cell < b.Cell : a.Depth < b.Depth; });
}

/// The merged OFB of the entries on `frame`: cells, depths, the arrays, the ghost flags.
bool Build(Work& w, const Arrays& arrays, const double* frame, vtkOFBPLICExchange& result)
{
  vtkOFB* merged = result.Merged;
  const vtkIdType dims[3] = { static_cast<vtkIdType>(frame[4]),
    static_cast<vtkIdType>(frame[5]),
    static_cast<vtkIdType>(frame[6]) };
  const vtkIdType total = static_cast<vtkIdType>(w.Entries.size());
  if (!merged->SetFrame(frame, frame[3], dims) ||
    (total > 0 && static_cast<vtkIdType>(w.Entries.back().Cell) >= merged->GetNumberOfCells()))
  {
    result.Problem = "the exchanged samples do not fit the frame";
    return false;
  }
  vtkTypeUInt32* offsets = merged->GetCellOffsets()->GetPointer(0);
  for (const Entry& e : w.Entries)
  {
    ++offsets[e.Cell + 1];
  }
  std::partial_sum(offsets, offsets + merged->GetNumberOfCells() + 1, offsets);
  if (!merged->AllocateSamples(total))
  {
    result.Problem = "out of memory";
    return false;
  }
  float* depths = merged->GetDepths()->GetPointer(0);
  vtkNew<vtkUnsignedCharArray> ghosts;
  ghosts->SetName(vtkDataSetAttributes::GhostArrayName());
  ghosts->SetNumberOfTuples(total);
  for (vtkIdType j = 0; j < total; ++j)
  {
    depths[j] = w.Entries[j].Depth;
    ghosts->SetValue(j, w.Entries[j].Source == w.Me ? 0 : 1);
    if (w.Entries[j].Source == w.Me)
    {
      result.InputToMerged[w.Entries[j].Index] = j;
    }
  }
  merged->BuildCellIndex();
  vtkPointData* pd = merged->GetSampleData();
  vtkPointData* inputData = w.Input ? w.Input->GetSampleData() : nullptr;
  size_t offset = 8;
  for (size_t a = 0; a < arrays.List.size(); ++a)
  {
    vtkDataArray* from = arrays.List[a];
    vtkSmartPointer<vtkDataArray> to;
    to.TakeReference(from->NewInstance());
    to->SetName(from->GetName());
    to->SetNumberOfComponents(from->GetNumberOfComponents());
    to->SetNumberOfTuples(total);
    auto* target = static_cast<unsigned char*>(to->GetVoidPointer(0));
    const size_t bytes = arrays.TupleBytes[a];
    for (vtkIdType j = 0; j < total; ++j)
    {
      const Entry& e = w.Entries[j];
      const unsigned char* source = e.Source == w.Me
        ? arrays.Tuple(a, e.Index)
        : w.Received[e.Source].data() + e.Index * arrays.RecordBytes + offset;
      std::memcpy(target + j * bytes, source, bytes);
    }
    offset += bytes;
    if (inputData->GetNormals() == from)
    {
      pd->SetNormals(to);
    }
    else if (inputData->GetVectors() == from)
    {
      pd->SetVectors(to);
    }
    else
    {
      pd->AddArray(to);
    }
  }
  pd->AddArray(ghosts);
  return true;
}

/// Each ghost sample of the input: the received sample of its cell nearest in depth,
/// within half a cell.
void MapGhosts(const Work& w, vtkOFBPLICExchange& result)
{
  vtkOFB* merged = result.Merged;
  const vtkTypeUInt32* offsets = merged->GetCellOffsets()->GetPointer(0);
  const float* depths = merged->GetDepths()->GetPointer(0);
  const double tolerance = 0.5 * merged->GetCellSize();
  for (vtkIdType i = 0; w.Ghosts && i < w.N; ++i)
  {
    if (w.Ghosts[i] == 0)
    {
      continue;
    }
    double best = tolerance;
    for (vtkIdType j = offsets[w.Cells[i]]; j < static_cast<vtkIdType>(offsets[w.Cells[i] + 1]);
         ++j)
    {
      const double d = std::abs(static_cast<double>(depths[j]) - w.Depths[i]);
      if (w.Entries[j].Source != w.Me && d <= best)
      {
        best = d;
        result.InputToMerged[i] = j;
      }
    }
  }
}
}

//------------------------------------------------------------------------------
bool vtkOFBPLICExchange::Run(vtkMultiProcessController* controller,
  vtkOFB* input,
  const std::vector<std::string>& names,
  double radius)
{
  Work w;
  w.Controller = controller;
  w.Size = controller->GetNumberOfProcesses();
  w.Me = controller->GetLocalProcessId();
  w.Input = input;
  w.N = input ? input->GetNumberOfSamples() : 0;
  auto* ghosts = w.N > 0 ? vtkUnsignedCharArray::SafeDownCast(input->GetSampleData()->GetArray(
                             vtkDataSetAttributes::GhostArrayName()))
                         : nullptr;
  w.Ghosts = ghosts && ghosts->GetNumberOfTuples() >= w.N ? ghosts->GetPointer(0) : nullptr;
  w.Cells = w.N > 0 ? input->GetCellIndex()->GetPointer(0) : nullptr;
  w.Depths = w.N > 0 ? input->GetDepths()->GetPointer(0) : nullptr;
  GatherBoxes(w);
  const double* frame = CommonFrame(w, this->Problem);
  this->Merged = vtkSmartPointer<vtkOFB>::New();
  this->InputToMerged.assign(static_cast<size_t>(w.N), -1);
  if (!frame)
  {
    // No process has samples (nothing to exchange), or the frames differ (every process
    // sees it and returns here).
    return this->Problem.empty();
  }
  const Arrays arrays(input, names);
  Select(w, arrays, radius);
  Transfer(w, arrays, *this);
  Collect(w, arrays, *this);
  if (!Build(w, arrays, frame, *this))
  {
    this->Merged = nullptr;
    return false;
  }
  MapGhosts(w, *this);
  return this->Problem.empty();
}
