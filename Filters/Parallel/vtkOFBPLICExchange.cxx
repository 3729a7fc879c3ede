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
}

//------------------------------------------------------------------------------
bool vtkOFBPLICExchange::Run(vtkMultiProcessController* controller,
  vtkOFB* input,
  const std::vector<std::string>& names,
  double radius)
{
  const int size = controller->GetNumberOfProcesses();
  const int me = controller->GetLocalProcessId();
  const vtkIdType n = input ? input->GetNumberOfSamples() : 0;
  auto* ghostArray = n > 0 ? vtkUnsignedCharArray::SafeDownCast(input->GetSampleData()->GetArray(
                               vtkDataSetAttributes::GhostArrayName()))
                           : nullptr;
  const unsigned char* ghosts =
    ghostArray && ghostArray->GetNumberOfTuples() >= n ? ghostArray->GetPointer(0) : nullptr;
  std::vector<vtkIdType> owned;
  std::vector<double> positions;
  double row[RowValues];
  std::fill(row, row + RowValues, 0.0);
  for (int a = 0; a < 3; ++a)
  {
    row[2 * a] = std::numeric_limits<double>::max();
    row[2 * a + 1] = std::numeric_limits<double>::lowest();
  }
  for (vtkIdType i = 0; i < n; ++i)
  {
    double x[3];
    if ((!ghosts || ghosts[i] == 0) && input->GetSamplePosition(i, x))
    {
      owned.push_back(i);
      positions.insert(positions.end(), x, x + 3);
      for (int a = 0; a < 3; ++a)
      {
        row[2 * a] = std::min(row[2 * a], x[a]);
        row[2 * a + 1] = std::max(row[2 * a + 1], x[a]);
      }
    }
  }
  row[6] = owned.empty() ? 0.0 : 1.0;
  if (input && input->GetCellSize() > 0.0)
  {
    for (int a = 0; a < 3; ++a)
    {
      row[7 + a] = input->GetOrigin()[a];
      row[11 + a] = static_cast<double>(input->GetDimensions()[a]);
    }
    row[10] = input->GetCellSize();
  }
  std::vector<double> rows(static_cast<size_t>(RowValues) * size);
  controller->AllGather(row, rows.data(), RowValues);

  // The common frame: that of every process that has one.
  const double* frame = nullptr;
  for (int r = 0; r < size; ++r)
  {
    const double* other = rows.data() + RowValues * r + 7;
    if (!(other[3] > 0.0))
    {
      continue;
    }
    if (frame && !std::equal(other, other + 7, frame))
    {
      this->Problem = "the processes' OFBs have different frames (sample them on one frame: "
                      "vtkOFBPSampler)";
      return false;
    }
    frame = frame ? frame : other;
  }
  this->Merged = vtkSmartPointer<vtkOFB>::New();
  this->InputToMerged.assign(static_cast<size_t>(n), -1);
  if (!frame)
  {
    return true; // no process has samples
  }

  // What goes to each process: the owned samples within `radius` of its owned samples' box.
  const Arrays arrays(input, names);
  std::vector<std::vector<vtkIdType>> selected(size);
  for (int r = 0; r < size && arrays.Valid && !owned.empty(); ++r)
  {
    const double* box = rows.data() + RowValues * r;
    if (r == me || box[6] == 0.0)
    {
      continue;
    }
    double lo[3], hi[3];
    bool meets = true;
    for (int a = 0; a < 3; ++a)
    {
      lo[a] = radius < 0.0 ? std::numeric_limits<double>::lowest() : box[2 * a] - radius;
      hi[a] = radius < 0.0 ? std::numeric_limits<double>::max() : box[2 * a + 1] + radius;
      meets = meets && row[2 * a] <= hi[a] && row[2 * a + 1] >= lo[a];
    }
    for (size_t k = 0; meets && k < owned.size(); ++k)
    {
      const double* x = positions.data() + 3 * k;
      if (x[0] >= lo[0] && x[0] <= hi[0] && x[1] >= lo[1] && x[1] <= hi[1] && x[2] >= lo[2] &&
        x[2] <= hi[2])
      {
        selected[r].push_back(owned[k]);
      }
    }
  }
  std::vector<vtkIdType> counts(2 * static_cast<size_t>(size), 0);
  for (int r = 0; r < size; ++r)
  {
    counts[2 * r] = static_cast<vtkIdType>(selected[r].size());
    counts[2 * r + 1] = counts[2 * r] * static_cast<vtkIdType>(arrays.RecordBytes);
  }
  std::vector<vtkIdType> table(2 * static_cast<size_t>(size) * size);
  controller->AllGather(counts.data(), table.data(), 2 * size);

  // One message each way per pair that has samples for the other.
  std::vector<std::vector<unsigned char>> received(size);
  const vtkTypeUInt32* cells = n > 0 ? input->GetCellIndex()->GetPointer(0) : nullptr;
  const float* depths = n > 0 ? input->GetDepths()->GetPointer(0) : nullptr;
  for (int round = 0; round < size + (size % 2) - 1; ++round)
  {
    const int p = Partner(me, round, size);
    if (p == me)
    {
      continue;
    }
    std::vector<unsigned char> message(static_cast<size_t>(counts[2 * p + 1]));
    unsigned char* out = message.data();
    for (vtkIdType i : selected[p])
    {
      std::memcpy(out, cells + i, 4);
      std::memcpy(out + 4, depths + i, 4);
      out += 8;
      for (size_t a = 0; a < arrays.List.size(); ++a)
      {
        std::memcpy(out, arrays.Tuple(a, i), arrays.TupleBytes[a]);
        out += arrays.TupleBytes[a];
      }
    }
    const vtkIdType expected = table[2 * static_cast<size_t>(size) * p + 2 * me + 1];
    received[p].resize(static_cast<size_t>(expected));
    for (int step = 0; step < 2; ++step)
    {
      if ((step == 0) == (me < p))
      {
        if (!message.empty())
        {
          controller->Send(message.data(), static_cast<vtkIdType>(message.size()), p, ExchangeTag);
        }
      }
      else if (expected > 0)
      {
        controller->Receive(received[p].data(), expected, p, ExchangeTag);
      }
    }
    this->SentSamples += counts[2 * p];
    this->SentBytes += counts[2 * p + 1];
    this->ReceivedBytes += expected;
  }

  // Own owned samples and the received ones, in the order of the processes, then sorted
  // as one process orders them: by cell, then depth.
  std::vector<Entry> entries;
  for (int r = 0; r < size; ++r)
  {
    if (r == me)
    {
      for (vtkIdType i : owned)
      {
        entries.push_back({ cells[i], depths[i], me, i });
      }
      continue;
    }
    const vtkIdType count = table[2 * static_cast<size_t>(size) * r + 2 * me];
    if (count == 0)
    {
      continue;
    }
    if (count * static_cast<vtkIdType>(arrays.RecordBytes) !=
      static_cast<vtkIdType>(received[r].size()))
    {
      this->Problem = "process " + std::to_string(r) + "'s samples do not have this process's "
                      "sample arrays";
      continue;
    }
    for (vtkIdType k = 0; k < count; ++k)
    {
      const unsigned char* record = received[r].data() + k * arrays.RecordBytes;
      Entry e{ 0, 0.0f, r, k };
      std::memcpy(&e.Cell, record, 4);
      std::memcpy(&e.Depth, record + 4, 4);
      entries.push_back(e);
    }
    this->ReceivedSamples += count;
  }
  std::stable_sort(entries.begin(),
    entries.end(),
    [](const Entry& a, const Entry& b)
    { return a.Cell != b.Cell ? a.Cell < b.Cell : a.Depth < b.Depth; });

  vtkOFB* merged = this->Merged;
  const vtkIdType dims[3] = { static_cast<vtkIdType>(frame[4]), static_cast<vtkIdType>(frame[5]),
    static_cast<vtkIdType>(frame[6]) };
  if (!merged->SetFrame(frame, frame[3], dims) ||
    (!entries.empty() && static_cast<vtkIdType>(entries.back().Cell) >= merged->GetNumberOfCells()))
  {
    this->Problem = "the exchanged samples do not fit the frame";
    this->Merged = nullptr;
    return false;
  }
  const vtkIdType total = static_cast<vtkIdType>(entries.size());
  vtkTypeUInt32* offsets = merged->GetCellOffsets()->GetPointer(0);
  for (const Entry& e : entries)
  {
    ++offsets[e.Cell + 1];
  }
  std::partial_sum(offsets, offsets + merged->GetNumberOfCells() + 1, offsets);
  if (!merged->AllocateSamples(total))
  {
    this->Problem = "out of memory";
    this->Merged = nullptr;
    return false;
  }
  float* mergedDepths = merged->GetDepths()->GetPointer(0);
  vtkNew<vtkUnsignedCharArray> mergedGhosts;
  mergedGhosts->SetName(vtkDataSetAttributes::GhostArrayName());
  mergedGhosts->SetNumberOfTuples(total);
  for (vtkIdType j = 0; j < total; ++j)
  {
    mergedDepths[j] = entries[j].Depth;
    mergedGhosts->SetValue(j, entries[j].Source == me ? 0 : 1);
    if (entries[j].Source == me)
    {
      this->InputToMerged[entries[j].Index] = j;
    }
  }
  merged->BuildCellIndex();
  vtkPointData* pd = merged->GetSampleData();
  size_t offset = 8;
  for (size_t a = 0; a < arrays.List.size(); ++a)
  {
    vtkDataArray* from = arrays.List[a];
    vtkSmartPointer<vtkDataArray> to;
    to.TakeReference(from->NewInstance());
    to->SetName(from->GetName());
    to->SetNumberOfComponents(from->GetNumberOfComponents());
    to->SetNumberOfTuples(total);
    unsigned char* target = static_cast<unsigned char*>(to->GetVoidPointer(0));
    const size_t bytes = arrays.TupleBytes[a];
    for (vtkIdType j = 0; j < total; ++j)
    {
      const Entry& e = entries[j];
      const unsigned char* source = e.Source == me
        ? arrays.Tuple(a, e.Index)
        : received[e.Source].data() + e.Index * arrays.RecordBytes + offset;
      std::memcpy(target + j * bytes, source, bytes);
    }
    offset += bytes;
    vtkPointData* inputData = input->GetSampleData();
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
  pd->AddArray(mergedGhosts);

  // A ghost sample: the owner's sample of its cell nearest in depth.
  const double tolerance = 0.5 * frame[3];
  for (vtkIdType i = 0; ghosts && i < n; ++i)
  {
    if (ghosts[i] == 0)
    {
      continue;
    }
    double best = tolerance;
    for (vtkIdType j = offsets[cells[i]]; j < static_cast<vtkIdType>(offsets[cells[i] + 1]); ++j)
    {
      const double d = std::abs(static_cast<double>(mergedDepths[j]) - depths[i]);
      if (entries[j].Source != me && d <= best)
      {
        best = d;
        this->InputToMerged[i] = j;
      }
    }
  }
  return this->Problem.empty();
}
