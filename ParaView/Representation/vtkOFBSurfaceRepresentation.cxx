#include "vtkOFBSurfaceRepresentation.h"

#include "vtkCellData.h"
#include "vtkCommunicator.h"
#include "vtkCompositeDataDisplayAttributes.h"
#include "vtkCompositeDataIterator.h"
#include "vtkCompositeDataSet.h"
#include "vtkDataArray.h"
#include "vtkDataObject.h"
#include "vtkDataSet.h"
#include "vtkDataSetAttributes.h"
#include "vtkFieldData.h"
#include "vtkInformation.h"
#include "vtkInformationRequestKey.h"
#include "vtkInformationVector.h"
#include "vtkMultiProcessController.h"
#include "vtkOFB.h"
#include "vtkOFBColoring.h"
#include "vtkOFBLIC.h"
#include "vtkOFBLICPyramid.h"
#include "vtkOFBPLIC.h"
#include "vtkOFBPLICPyramid.h"
#include "vtkOFBPSampler.h"
#include "vtkOFBParaViewProbe.h"
#include "vtkOFBPolyDataMapper.h"
#include "vtkOFBSamplePack.h"
#include "vtkOFBSampler.h"
#include "vtkObjectFactory.h"
#include "vtkPVRenderView.h"
#include "vtkPVView.h"
#include "vtkPointData.h"
#include "vtkPolyData.h"
#include "vtkProcessModule.h"
#include "vtkScalarsToColors.h"
#include "vtkSmartPointer.h"

#include <algorithm>
#include <cmath>

vtkStandardNewMacro(vtkOFBSurfaceRepresentation);

namespace
{
/// Under MPI the LIC and the pyramid's levels read every process's owned samples within
/// reach, whatever the input's ghost depth (vtkOFBPLIC exchange, vtkOFBPLICPyramid, by
/// every process together: SynchronizePyramid); no filter cache (hits differ per process).
vtkSmartPointer<vtkOFBLICPyramid> vtkOFBSurfaceRepresentationDistributeLIC(vtkOFBPLIC* lic)
{
  lic->SetGhostSamples(vtkOFBPLIC::GHOST_SAMPLES_EXCHANGE);
  auto pyramid = vtkSmartPointer<vtkOFBPLICPyramid>::New();
  pyramid->DeferLevelLICsOn();
  pyramid->SetFilterCacheSize(0);
  return pyramid;
}
}

//------------------------------------------------------------------------------
vtkOFBSurfaceRepresentation::vtkOFBSurfaceRepresentation()
  : OFBMapper(vtkOFBPolyDataMapper::New())
  , Sampler(vtkOFBPSampler::New())
  , LIC(vtkOFBPLIC::New())
  , OFBLIC(false)
  , UseInputOFB(true)
  , VectorsAssociation(vtkDataObject::FIELD_ASSOCIATION_POINTS)
  , WarnedNoVectors(false)
  , AnyLICField(false)
  , AnyInputOFB(false)
  , AnyInputLIC(false)
  , EmptyPiece(vtkSmartPointer<vtkPolyData>::New())
  , EmptyOFB(vtkSmartPointer<vtkOFB>::New())
  , LICPyramid(vtkSmartPointer<vtkOFBLICPyramid>::New())
  , OFBSource(nullptr)
  , GhostedCells(0)
  , DeliveredPacks(vtkSmartPointer<vtkOFBSamplePack>::New())
{
  std::fill(this->OFBFrame, this->OFBFrame + 7, 0.0);
  // The OFB mapper replaces the superclass's full-resolution mapper; the LOD mapper stays.
  this->Mapper->Delete();
  this->Mapper = this->OFBMapper;
  vtkNew<vtkCompositeDataDisplayAttributes> attributes;
  this->OFBMapper->SetCompositeDataDisplayAttributes(attributes);

  // A change of the colour array, the solid colour or the time step keeps the structure.
  this->Sampler->SetStructureReuseToAlways();
  // The representation cannot ask the delivered surface for ghost cells: the LIC reads
  // those the surface has (a request would make the pipeline execute at every update).
  this->LIC->SetNumberOfGhostLevels(0);
  this->LIC->SetInputConnection(this->Sampler->GetOutputPort());
  // Under MPI the mapper is handed the OFB's data (SynchronizeOFB), never the pipeline:
  // it would update it in its own time, on one process alone.
  vtkMultiProcessController* controller = this->Sampler->GetController();
  if (controller && controller->GetNumberOfProcesses() > 1)
  {
    this->OFBSource = this->Sampler;
  }
  else
  {
    this->OFBMapper->SetOFBConnection(this->Sampler->GetOutputPort());
  }
  this->OFBMapper->GetColoring()->SetLICIntensity(0.8);
  // Under MPI the LIC and its levels read the samples of every process within reach.
  if (this->OFBSource)
  {
    this->LICPyramid = vtkOFBSurfaceRepresentationDistributeLIC(this->LIC);
  }

  // Connects the new mapper to the actor, the selection and the backface actor.
  this->SetupDefaults();
}

//------------------------------------------------------------------------------
vtkOFBSurfaceRepresentation::~vtkOFBSurfaceRepresentation()
{
  // this->Mapper (the OFB mapper) is deleted by the superclass.
  this->Sampler->Delete();
  this->LIC->Delete();
}

//------------------------------------------------------------------------------
int vtkOFBSurfaceRepresentation::RequestData(vtkInformation* request,
  vtkInformationVector** inputVector,
  vtkInformationVector* outputVector)
{
  vtkDataObject* input = inputVector[0]->GetNumberOfInformationObjects() == 1
    ? vtkDataObject::GetData(inputVector[0], 0)
    : nullptr;
  this->InputOFB = input ? vtkOFBParaViewProbe::GetOFB(input) : nullptr;
  // Under MPI, a surface with ghost cells is sampled as it is: ParaView's geometry filter
  // removes the ghost cells from the surface it delivers, and the LIC reads their samples
  // across the piece borders.
  vtkMultiProcessController* controller = this->Sampler->GetController();
  this->GhostedInput = nullptr;
  if (controller && controller->GetNumberOfProcesses() > 1 &&
    vtkOFBSurfaceRepresentation::HasGhostCells(input))
  {
    this->GhostedInput.TakeReference(input->NewInstance());
    this->GhostedInput->ShallowCopy(input);
    this->GhostedCells = vtkOFBSurfaceRepresentation::CountCells(input, true);
  }
  if (!this->Superclass::RequestData(request, inputVector, outputVector))
  {
    return 0;
  }
  this->PackInputOFB();
  return 1;
}

//------------------------------------------------------------------------------
void vtkOFBSurfaceRepresentation::PackInputOFB()
{
  // On a server, which delivers the surface to a client that may render it locally (not
  // in pvbatch or a builtin session, which render where the OFB is).
  const int type = vtkProcessModule::GetProcessType();
  if (this->UseInputOFB && this->InputOFB &&
    (type == vtkProcessModule::PROCESS_SERVER || type == vtkProcessModule::PROCESS_DATA_SERVER))
  {
    vtkOFBSamplePack::PackIntoBlocks(this->GetRenderedDataObject(0),
      this->InputOFB,
      this->Sampler->GetController() ? this->Sampler->GetController()->GetLocalProcessId() : 0);
  }
}

//------------------------------------------------------------------------------
int vtkOFBSurfaceRepresentation::ProcessViewRequest(vtkInformationRequestKey* requestType,
  vtkInformation* inInfo,
  vtkInformation* outInfo)
{
  if (requestType == vtkPVView::REQUEST_RENDER())
  {
    // Where the input OFB is not in this process (a client rendering a server's surface
    // locally): the one packed into the delivered surface (PackInputOFB). Before the
    // superclass's colouring parameters, which choose the OFB the mapper reads.
    this->DeliveredOFB = this->DeliveredPacks->UpdateMergedOFB(
      this->UseInputOFB && !this->InputOFB ? vtkPVView::GetDeliveredPiece(inInfo, this) : nullptr);
  }
  if (!this->Superclass::ProcessViewRequest(requestType, inInfo, outInfo))
  {
    return 0;
  }
  if (requestType == vtkPVView::REQUEST_RENDER())
  {
    // The superclass gave the delivered surface to the mapper; the OFB is built from the
    // same surface, where it is rendered: when the mapper updates its OFB input, or under
    // MPI here (SynchronizeOFB). A process without a piece samples an empty surface (it
    // still takes part in the collective calls).
    vtkDataObject* data = vtkPVView::GetDeliveredPiece(inInfo, this);
    // The input with its ghost cells where the view renders it as it is (not where the
    // view moved the surface between processes, for ordered compositing).
    const bool ghosted = this->GhostedInput &&
      vtkOFBSurfaceRepresentation::CountCells(data, false) == this->GhostedCells;
    vtkDataObject* samplerInput = ghosted ? this->GhostedInput.Get()
      : data                              ? data
                                          : this->EmptyPiece.Get();
    if (this->Sampler->GetInputDataObject(0, 0) != samplerInput)
    {
      this->Sampler->SetInputDataObject(samplerInput);
    }
    if (data)
    {
      this->PopulateBlockAttributes(this->OFBMapper->GetCompositeDataDisplayAttributes(), data);
    }
    this->SynchronizeOFB();
  }
  return 1;
}

//------------------------------------------------------------------------------
void vtkOFBSurfaceRepresentation::SynchronizeOFB()
{
  vtkMultiProcessController* controller = this->Sampler->GetController();
  if (!controller || controller->GetNumberOfProcesses() <= 1)
  {
    return;
  }
  // What the pieces have, agreed by all processes: the LIC runs, and reads an input OFB,
  // on every process or on none.
  vtkOFB* inputOFB = this->InputOFB.Get();
  int local[3] = { this->OFBLIC && this->UpdateVectors() ? 1 : 0,
    inputOFB ? 1 : 0,
    inputOFB && inputOFB->GetSampleData()->GetArray("LIC") ? 1 : 0 };
  int global[3] = { 0, 0, 0 };
  controller->AllReduce(local, global, 3, vtkCommunicator::MAX_OP);
  if ((global[0] != 0) != this->AnyLICField || (global[1] != 0) != this->AnyInputOFB ||
    (global[2] != 0) != this->AnyInputLIC)
  {
    this->AnyLICField = global[0] != 0;
    this->AnyInputOFB = global[1] != 0;
    this->AnyInputLIC = global[2] != 0;
    this->UpdateLICConnection();
  }

  // The OFB the mapper reads is brought up to date here, by every process together,
  // whenever one of them needs it, and handed to the mapper as data.
  vtkAlgorithm* source = this->OFBSource;
  int stale = source && vtkOFBSurfaceRepresentation::NeedsUpdate(source) ? 1 : 0;
  int anyStale = 0;
  controller->AllReduce(&stale, &anyStale, 1, vtkCommunicator::MAX_OP);
  // The mapper's automatic LIC pyramid (AutomaticLevelLIC) follows a LIC connected to it:
  // here the LIC is given.
  vtkOFBPyramid* pyramid = source == this->LIC &&
      this->OFBMapper->GetLookupMode() == vtkOFBPolyDataMapper::LOOKUP_AUTOMATIC &&
      this->OFBMapper->GetAutomaticLevelLIC()
    ? this->LICPyramid.Get()
    : nullptr;
  if (pyramid && this->LICPyramid->GetLIC() != this->LIC)
  {
    this->LICPyramid->SetLIC(this->LIC);
  }
  if ((this->OFBMapper->GetPyramid() == this->LICPyramid) != (pyramid != nullptr))
  {
    this->OFBMapper->SetPyramid(pyramid);
  }
  if (!source)
  {
    return; // the input's OFB, as it is (UpdateLICConnection)
  }
  if (anyStale)
  {
    // The first algorithm of the chain, so that every process runs all of it.
    vtkAlgorithm* first =
      source == this->Sampler || this->LIC->GetInputAlgorithm(0, 0) == this->Sampler
      ? static_cast<vtkAlgorithm*>(this->Sampler)
      : static_cast<vtkAlgorithm*>(this->LIC);
    first->Modified();
    source->Update();
  }
  vtkOFB* ofb = vtkOFB::SafeDownCast(source->GetOutputDataObject(0));
  if (this->OFBMapper->GetOFB() != ofb)
  {
    this->OFBMapper->SetOFB(ofb);
  }
  if (pyramid)
  {
    this->SynchronizePyramid(ofb);
  }
}

//------------------------------------------------------------------------------
void vtkOFBSurfaceRepresentation::SynchronizePyramid(vtkOFB* ofb)
{
  // The levels as the mapper sets them at its render (vtkOFBShaderStorage::UpdateLevels),
  // so that its render finds them up to date; their LICs (vtkOFBPLIC, deferred: collective
  // calls) computed here by every process together, also one whose piece or levels are
  // empty, whenever one of them needs them.
  vtkOFBLICPyramid* pyramid = this->LICPyramid;
  int local[2] = { 0, 0 };
  if (ofb && ofb->GetNumberOfSamples() > 0 && this->OFBMapper->GetRenderedSurface())
  {
    pyramid->SetInputOFB(ofb);
    pyramid->SetSurface(this->OFBMapper->GetRenderedSurface());
    // The levels sample what level 0 sampled: the input with its ghost cells where the
    // sampler reads it, so that their LICs read across the piece borders too.
    vtkPolyData* ghosted = vtkPolyData::SafeDownCast(this->GhostedInput);
    pyramid->SetLevelSurface(
      ghosted && this->Sampler->GetInputDataObject(0, 0) == ghosted ? ghosted : nullptr);
    pyramid->SetMaximumNumberOfLevels(this->OFBMapper->GetMaximumNumberOfMipmapLevels());
    pyramid->SetMinimumResolution(this->OFBMapper->GetMinimumMipmapResolution());
    if (pyramid->UpdateLevels())
    {
      local[0] = pyramid->GetLevelLICsPending() ? 1 : 0;
      local[1] = pyramid->GetNumberOfLevels();
    }
  }
  int global[2] = { 0, 0 };
  this->Sampler->GetController()->AllReduce(local, global, 2, vtkCommunicator::MAX_OP);
  if (global[0])
  {
    pyramid->ComputeLevelLICs(global[1]);
  }
}

//------------------------------------------------------------------------------
bool vtkOFBSurfaceRepresentation::NeedsUpdate(vtkAlgorithm* algorithm)
{
  vtkDataObject* output = algorithm->GetOutputDataObject(0);
  if (!output || output->GetUpdateTime() < algorithm->GetMTime())
  {
    return true;
  }
  const vtkMTimeType updated = output->GetUpdateTime();
  for (int port = 0; port < algorithm->GetNumberOfInputPorts(); ++port)
  {
    for (int c = 0; c < algorithm->GetNumberOfInputConnections(port); ++c)
    {
      vtkDataObject* input = algorithm->GetInputDataObject(port, c);
      vtkAlgorithm* producer = algorithm->GetInputAlgorithm(port, c);
      if ((input && input->GetMTime() > updated) ||
        (producer && producer->GetNumberOfInputPorts() > 0 &&
          vtkOFBSurfaceRepresentation::NeedsUpdate(producer)))
      {
        return true;
      }
    }
  }
  return false;
}

//------------------------------------------------------------------------------
double* vtkOFBSurfaceRepresentation::GetOFBFrame()
{
  std::fill(this->OFBFrame, this->OFBFrame + 7, 0.0);
  vtkOFB* ofb = this->OFBMapper->GetOFB();
  const bool fromLIC = this->OFBSource == this->LIC ||
    (this->OFBMapper->GetNumberOfInputConnections(1) > 0 &&
      this->OFBMapper->GetInputAlgorithm(1, 0) == this->LIC);
  if ((!ofb || !(ofb->GetCellSize() > 0.0)) && fromLIC)
  {
    // A LIC that output nothing (a piece without the field): the frame of the OFB it reads.
    ofb = vtkOFB::SafeDownCast(this->LIC->GetInputDataObject(0, 0));
  }
  if (!ofb || !(ofb->GetCellSize() > 0.0))
  {
    return this->OFBFrame;
  }
  const double* origin = ofb->GetOrigin();
  const vtkIdType* dimensions = ofb->GetDimensions();
  for (int a = 0; a < 3; ++a)
  {
    this->OFBFrame[a] = origin[a];
    this->OFBFrame[4 + a] = static_cast<double>(dimensions[a]);
  }
  this->OFBFrame[3] = ofb->GetCellSize();
  return this->OFBFrame;
}

//------------------------------------------------------------------------------
vtkOFBSampler* vtkOFBSurfaceRepresentation::GetOFBSampler()
{
  return this->Sampler;
}

//------------------------------------------------------------------------------
vtkOFBLIC* vtkOFBSurfaceRepresentation::GetOFBLICFilter()
{
  return this->LIC;
}

//------------------------------------------------------------------------------
void vtkOFBSurfaceRepresentation::UpdateColoringParameters()
{
  this->Superclass::UpdateColoringParameters();
  this->UpdateColorSource();
  this->UpdateLICConnection();
}

//------------------------------------------------------------------------------
void vtkOFBSurfaceRepresentation::UpdateColorSource()
{
  vtkOFBColoring* coloring = this->OFBMapper->GetColoring();
  const char* name = this->GetColorArrayName();
  vtkInformation* info = this->GetInputArrayInformation(0);
  const int association = (info && info->Has(vtkDataObject::FIELD_ASSOCIATION()))
    ? info->Get(vtkDataObject::FIELD_ASSOCIATION())
    : vtkDataObject::FIELD_ASSOCIATION_POINTS;
  // Direct colours (Map Scalars off: the "Colors" of an OFB Probe, RGB(A) bytes) are the
  // paint, which the samples hold as "Colors".
  const bool scalars = name && name[0] && association != vtkDataObject::FIELD_ASSOCIATION_NONE &&
    this->OFBMapper->GetColorMode() != VTK_COLOR_MODE_DIRECT_SCALARS;

  // The OFB colours the surface: the mapper's per-vertex scalar colours play no part.
  this->OFBMapper->ScalarVisibilityOff();
  if (!scalars)
  {
    coloring->SetColorSourceToPaint();
    return;
  }

  // A cell array whose name a point array has too: the samples take the cell array.
  this->Sampler->SetArrayPrecedence(association == vtkDataObject::FIELD_ASSOCIATION_CELLS
      ? vtkOFBSampler::CELL_ARRAYS_FIRST
      : vtkOFBSampler::POINT_ARRAYS_FIRST);

  vtkScalarsToColors* lut = this->OFBMapper->GetLookupTable();
  int component = 0;
  const int components = vtkOFBSurfaceRepresentation::GetNumberOfComponents(
    this->OFBMapper->GetInputDataObject(0, 0), association, name);
  if (components > 1)
  {
    component = lut->GetVectorMode() == vtkScalarsToColors::COMPONENT
      ? std::min(lut->GetVectorComponent(), components - 1)
      : -1;
  }
  coloring->SetColorSourceToScalars();
  coloring->SetScalarArrayName(name);
  coloring->SetScalarComponent(component);
  coloring->SetLookupTable(lut);
  // ParaView's colour map carries its range (rescaled by the colour map editor).
  coloring->UseLookupTableScalarRangeOn();
}

//------------------------------------------------------------------------------
void vtkOFBSurfaceRepresentation::UpdateLICConnection()
{
  // Under MPI, what any process's piece has (SynchronizeOFB): a process whose piece is
  // empty runs the LIC too, on an empty OFB where it has no input OFB.
  vtkMultiProcessController* controller = this->Sampler->GetController();
  const bool parallel = controller && controller->GetNumberOfProcesses() > 1;
  const bool lic = this->UpdateVectors() || (parallel && this->OFBLIC && this->AnyLICField);
  vtkOFB* inputOFB = !this->UseInputOFB ? nullptr
    : this->InputOFB                    ? this->InputOFB.Get()
    : parallel && this->AnyInputOFB     ? this->EmptyOFB.Get()
                                        : this->DeliveredOFB.Get();
  vtkOFBColoring* coloring = this->OFBMapper->GetColoring();
  const bool inputLIC =
    inputOFB && (inputOFB->GetSampleData()->GetArray("LIC") || (parallel && this->AnyInputLIC));
  const bool noField = this->OFBLIC && !lic && !inputLIC;
  if (noField && !this->WarnedNoVectors)
  {
    vtkWarningMacro("OFB LIC is on but the surface has no such vector field (3 components): "
                    "showing the colours without LIC.");
  }
  this->WarnedNoVectors = noField;
  if (inputOFB && (inputLIC || !lic))
  {
    // The input's OFB as it is: its paint, its arrays and its own LIC, if any.
    this->OFBSource = nullptr;
    if (this->OFBMapper->GetOFB() != inputOFB)
    {
      this->OFBMapper->SetOFB(inputOFB);
    }
    coloring->SetIntensityModulation(this->OFBLIC && inputLIC);
    coloring->SetIntensityArrayName("LIC");
    return;
  }
  if (inputOFB)
  {
    // The LIC computed here on the input's OFB.
    if (this->LIC->GetInputDataObject(0, 0) != inputOFB)
    {
      this->LIC->SetInputData(inputOFB);
    }
  }
  else if (this->LIC->GetInputAlgorithm(0, 0) != this->Sampler)
  {
    this->LIC->SetInputConnection(this->Sampler->GetOutputPort());
  }
  vtkAlgorithm* source =
    lic ? static_cast<vtkAlgorithm*>(this->LIC) : static_cast<vtkAlgorithm*>(this->Sampler);
  if (parallel)
  {
    this->OFBSource = source;
  }
  else if (this->OFBMapper->GetInputAlgorithm(1, 0) != source)
  {
    this->OFBMapper->SetOFBConnection(source->GetOutputPort());
  }
  coloring->SetIntensityModulation(lic);
  coloring->SetIntensityArrayName("LIC");
}

//------------------------------------------------------------------------------
bool vtkOFBSurfaceRepresentation::UpdateVectors()
{
  // The sampler projects a point field into the tangent planes and makes it the samples'
  // active vectors; a cell field is a sample array of its name, which the LIC reads (it
  // removes the normal component of any field). Without the LIC, or without the array in
  // the surface, the sampler keeps its default (the active point vectors, if any), so
  // that a missing field never empties the OFB.
  vtkDataObject* data = this->OFBMapper->GetInputDataObject(0, 0);
  const bool named = this->OFBLIC && !this->VectorsName.empty() &&
    vtkOFBSurfaceRepresentation::GetNumberOfComponents(
      data, this->VectorsAssociation, this->VectorsName.c_str()) == 3;
  const bool active = this->OFBLIC && !named &&
    vtkOFBSurfaceRepresentation::GetNumberOfComponents(
      data, vtkDataObject::FIELD_ASSOCIATION_POINTS, nullptr) == 3;
  const bool points = named && this->VectorsAssociation == vtkDataObject::FIELD_ASSOCIATION_POINTS;
  const std::string samplerVectors = points ? this->VectorsName : std::string();
  if (samplerVectors != this->SamplerVectors)
  {
    this->SamplerVectors = samplerVectors;
    if (points)
    {
      this->Sampler->SetInputArrayToProcess(
        0, 0, 0, vtkDataObject::FIELD_ASSOCIATION_POINTS, samplerVectors.c_str());
    }
    else
    {
      this->Sampler->SetInputArrayToProcess(
        0, 0, 0, vtkDataObject::FIELD_ASSOCIATION_POINTS, vtkDataSetAttributes::VECTORS);
    }
  }
  const std::string licVectors = named ? this->VectorsName : std::string();
  if (licVectors != this->LICVectors)
  {
    this->LICVectors = licVectors;
    if (named)
    {
      this->LIC->SetInputArrayToProcess(
        0, 0, 0, vtkDataObject::FIELD_ASSOCIATION_POINTS, licVectors.c_str());
    }
    else
    {
      this->LIC->SetInputArrayToProcess(
        0, 0, 0, vtkDataObject::FIELD_ASSOCIATION_POINTS, vtkDataSetAttributes::VECTORS);
    }
  }
  return named || active;
}

//------------------------------------------------------------------------------
vtkIdType vtkOFBSurfaceRepresentation::CountCells(vtkDataObject* data, bool ownedOnly)
{
  vtkIdType count = 0;
  auto visit = [&count, ownedOnly](vtkDataObject* object)
  {
    vtkDataSet* dataSet = vtkDataSet::SafeDownCast(object);
    if (!dataSet)
    {
      return;
    }
    vtkDataArray* ghosts = ownedOnly
      ? dataSet->GetCellData()->GetArray(vtkDataSetAttributes::GhostArrayName())
      : nullptr;
    if (!ghosts)
    {
      count += dataSet->GetNumberOfCells();
      return;
    }
    for (vtkIdType i = 0; i < ghosts->GetNumberOfTuples(); ++i)
    {
      count += ghosts->GetComponent(i, 0) == 0.0 ? 1 : 0;
    }
  };
  if (vtkCompositeDataSet* composite = vtkCompositeDataSet::SafeDownCast(data))
  {
    vtkSmartPointer<vtkCompositeDataIterator> it;
    it.TakeReference(composite->NewIterator());
    for (it->InitTraversal(); !it->IsDoneWithTraversal(); it->GoToNextItem())
    {
      visit(it->GetCurrentDataObject());
    }
  }
  else
  {
    visit(data);
  }
  return count;
}

//------------------------------------------------------------------------------
bool vtkOFBSurfaceRepresentation::HasGhostCells(vtkDataObject* data)
{
  // Polygonal data only: the delivered surface of other data is not made of its cells.
  bool ghosts = false;
  bool polygonal = true;
  auto visit = [&ghosts, &polygonal](vtkDataObject* object)
  {
    vtkPolyData* polyData = vtkPolyData::SafeDownCast(object);
    polygonal = polygonal && polyData;
    ghosts = ghosts ||
      (polyData &&
        polyData->GetCellData()->GetArray(vtkDataSetAttributes::GhostArrayName()) != nullptr);
  };
  if (vtkCompositeDataSet* composite = vtkCompositeDataSet::SafeDownCast(data))
  {
    vtkSmartPointer<vtkCompositeDataIterator> it;
    it.TakeReference(composite->NewIterator());
    for (it->InitTraversal(); !it->IsDoneWithTraversal(); it->GoToNextItem())
    {
      visit(it->GetCurrentDataObject());
    }
  }
  else if (data)
  {
    visit(data);
  }
  return ghosts && polygonal;
}

//------------------------------------------------------------------------------
int vtkOFBSurfaceRepresentation::GetNumberOfComponents(vtkDataObject* data,
  int association,
  const char* name)
{
  auto componentsOf = [association, name](vtkDataObject* object)
  {
    vtkDataSet* dataSet = vtkDataSet::SafeDownCast(object);
    vtkFieldData* fields = !dataSet ? nullptr
      : association == vtkDataObject::FIELD_ASSOCIATION_CELLS
      ? static_cast<vtkFieldData*>(dataSet->GetCellData())
      : static_cast<vtkFieldData*>(dataSet->GetPointData());
    vtkDataArray* array = !fields ? nullptr
      : name                      ? fields->GetArray(name)
                                  : dataSet->GetPointData()->GetVectors();
    return array ? array->GetNumberOfComponents() : 0;
  };
  if (vtkCompositeDataSet* composite = vtkCompositeDataSet::SafeDownCast(data))
  {
    vtkSmartPointer<vtkCompositeDataIterator> it;
    it.TakeReference(composite->NewIterator());
    for (it->InitTraversal(); !it->IsDoneWithTraversal(); it->GoToNextItem())
    {
      if (const int components = componentsOf(it->GetCurrentDataObject()))
      {
        return components;
      }
    }
    return 0;
  }
  return componentsOf(data);
}

//------------------------------------------------------------------------------
void vtkOFBSurfaceRepresentation::SetOFBResolution(int resolution)
{
  if (resolution != this->Sampler->GetResolution())
  {
    this->Sampler->SetResolution(resolution);
    this->MarkModified();
  }
}

//------------------------------------------------------------------------------
int vtkOFBSurfaceRepresentation::GetOFBResolution()
{
  return this->Sampler->GetResolution();
}

//------------------------------------------------------------------------------
void vtkOFBSurfaceRepresentation::SetOFBLookupMode(int mode)
{
  this->OFBMapper->SetLookupMode(mode);
}

//------------------------------------------------------------------------------
int vtkOFBSurfaceRepresentation::GetOFBLookupMode()
{
  return this->OFBMapper->GetLookupMode();
}

//------------------------------------------------------------------------------
void vtkOFBSurfaceRepresentation::SetUseInputOFB(bool use)
{
  if (use != this->UseInputOFB)
  {
    this->UseInputOFB = use;
    // The delivered surface carries the input OFB where it is used (PackInputOFB).
    this->MarkModified();
  }
}

//------------------------------------------------------------------------------
vtkOFB* vtkOFBSurfaceRepresentation::GetRenderedOFB()
{
  return this->OFBMapper->GetOFB();
}

//------------------------------------------------------------------------------
void vtkOFBSurfaceRepresentation::SetOFBLIC(bool enable)
{
  if (enable != this->OFBLIC)
  {
    this->OFBLIC = enable;
    this->Modified();
  }
}

//------------------------------------------------------------------------------
void vtkOFBSurfaceRepresentation::SelectOFBInputVectors(int,
  int,
  int,
  int fieldAssociation,
  const char* name)
{
  const std::string vectors = name ? name : "";
  if (vectors != this->VectorsName || fieldAssociation != this->VectorsAssociation)
  {
    this->VectorsName = vectors;
    this->VectorsAssociation = fieldAssociation;
    this->Modified();
  }
}

//------------------------------------------------------------------------------
void vtkOFBSurfaceRepresentation::SetOFBNumberOfSteps(int steps)
{
  this->LIC->SetNumberOfSteps(steps);
}

//------------------------------------------------------------------------------
void vtkOFBSurfaceRepresentation::SetOFBStepSize(double size)
{
  this->LIC->SetStepSize(size);
}

//------------------------------------------------------------------------------
void vtkOFBSurfaceRepresentation::SetOFBNoiseGrainSize(double size)
{
  this->LIC->SetNoiseGrainSize(size);
}

//------------------------------------------------------------------------------
void vtkOFBSurfaceRepresentation::SetOFBEnhancedLIC(bool enhanced)
{
  this->LIC->SetEnhancedLIC(enhanced);
}

//------------------------------------------------------------------------------
void vtkOFBSurfaceRepresentation::SetOFBNormalizeVectors(bool normalize)
{
  this->LIC->SetNormalizeVectors(normalize);
}

//------------------------------------------------------------------------------
void vtkOFBSurfaceRepresentation::SetOFBLICColorMode(int mode)
{
  this->OFBMapper->GetColoring()->SetLICColorMode(mode);
}

//------------------------------------------------------------------------------
void vtkOFBSurfaceRepresentation::SetOFBLICIntensity(double intensity)
{
  this->OFBMapper->GetColoring()->SetLICIntensity(intensity);
}

//------------------------------------------------------------------------------
void vtkOFBSurfaceRepresentation::SetOFBMapModeBias(double bias)
{
  this->OFBMapper->GetColoring()->SetMapModeBias(bias);
}

//------------------------------------------------------------------------------
void vtkOFBSurfaceRepresentation::SetDiffuseColor(double r, double g, double b)
{
  this->Superclass::SetDiffuseColor(r, g, b);
  auto toByte = [](double v)
  { return static_cast<unsigned char>(std::lround(255.0 * std::min(1.0, std::max(0.0, v)))); };
  this->Sampler->SetDefaultColor(toByte(r), toByte(g), toByte(b), 255);
}

//------------------------------------------------------------------------------
void vtkOFBSurfaceRepresentation::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "OFBResolution: " << this->Sampler->GetResolution() << "\n";
  os << indent << "OFBLookupMode: "
     << vtkOFBPolyDataMapper::GetLookupModeAsString(this->OFBMapper->GetLookupMode()) << "\n";
  os << indent << "UseInputOFB: " << (this->UseInputOFB ? "On" : "Off") << "\n";
  os << indent << "InputOFB: " << this->InputOFB.Get() << "\n";
  os << indent << "DeliveredOFB: " << this->DeliveredOFB.Get() << "\n";
  os << indent << "Controller: " << this->Sampler->GetController() << "\n";
  os << indent << "OFBLIC: " << (this->OFBLIC ? "On" : "Off") << "\n";
  os << indent
     << "OFBInputVectors: " << (this->VectorsName.empty() ? "(active)" : this->VectorsName)
     << " (association " << this->VectorsAssociation << ")\n";
  os << indent << "OFBNumberOfSteps: " << this->LIC->GetNumberOfSteps() << "\n";
  os << indent << "OFBStepSize: " << this->LIC->GetStepSize() << "\n";
  os << indent << "OFBNoiseGrainSize: " << this->LIC->GetNoiseGrainSize() << "\n";
  os << indent << "OFBEnhancedLIC: " << (this->LIC->GetEnhancedLIC() ? "On" : "Off") << "\n";
  os << indent << "OFBNormalizeVectors: " << (this->LIC->GetNormalizeVectors() ? "On" : "Off")
     << "\n";
  vtkOFBColoring* coloring = this->OFBMapper->GetColoring();
  os << indent
     << "OFBLICColorMode: " << vtkOFBColoring::GetLICColorModeAsString(coloring->GetLICColorMode())
     << "\n";
  os << indent << "OFBLICIntensity: " << coloring->GetLICIntensity() << "\n";
  os << indent << "OFBMapModeBias: " << coloring->GetMapModeBias() << "\n";
}
