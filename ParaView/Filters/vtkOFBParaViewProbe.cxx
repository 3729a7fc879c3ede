#include "vtkOFBParaViewProbe.h"

#include "vtkAbstractArray.h"
#include "vtkInformation.h"
#include "vtkInformationDataObjectKey.h"
#include "vtkInformationVector.h"
#include "vtkOFB.h"
#include "vtkObjectFactory.h"
#include "vtkPointData.h"
#include "vtkPolyData.h"
#include "vtkWeakPointer.h"

#include <map>
#include <mutex>
#include <utility>

vtkStandardNewMacro(vtkOFBParaViewProbe);
vtkInformationKeyMacro(vtkOFBParaViewProbe, OFB, DataObject);

//------------------------------------------------------------------------------
vtkOFBParaViewProbe::vtkOFBParaViewProbe() = default;

//------------------------------------------------------------------------------
vtkOFBParaViewProbe::~vtkOFBParaViewProbe() = default;

namespace
{
/// The probe outputs' "vtkValidPointMask" arrays and the OFBs probed into them, both
/// held weakly: a shallow copy of an output shares the array and finds the OFB.
class MaskRegistry
{
public:
  void Add(vtkAbstractArray* mask, vtkOFB* ofb)
  {
    std::lock_guard<std::mutex> lock(this->Mutex);
    for (auto it = this->Entries.begin(); it != this->Entries.end();)
    {
      it = (!it->second.first || !it->second.second) ? this->Entries.erase(it) : std::next(it);
    }
    this->Entries[mask] = { mask, ofb };
  }
  vtkOFB* Find(vtkAbstractArray* mask)
  {
    std::lock_guard<std::mutex> lock(this->Mutex);
    auto it = this->Entries.find(mask);
    return (it != this->Entries.end() && it->second.first == mask) ? it->second.second.Get()
                                                                   : nullptr;
  }

private:
  std::mutex Mutex;
  std::map<vtkAbstractArray*, std::pair<vtkWeakPointer<vtkAbstractArray>, vtkWeakPointer<vtkOFB>>>
    Entries;
};

MaskRegistry& Registry()
{
  static MaskRegistry registry;
  return registry;
}

constexpr const char* MaskName = "vtkValidPointMask";
}

//------------------------------------------------------------------------------
vtkOFB* vtkOFBParaViewProbe::GetOFB(vtkDataObject* data)
{
  if (!data)
  {
    return nullptr;
  }
  if (vtkOFB* ofb = vtkOFB::SafeDownCast(data->GetInformation()->Get(OFB())))
  {
    return ofb;
  }
  vtkFieldData* points = data->GetAttributesAsFieldData(vtkDataObject::POINT);
  vtkAbstractArray* mask = points ? points->GetAbstractArray(MaskName) : nullptr;
  return mask ? Registry().Find(mask) : nullptr;
}

//------------------------------------------------------------------------------
int vtkOFBParaViewProbe::RequestData(vtkInformation* request,
  vtkInformationVector** inInfo,
  vtkInformationVector* outInfo)
{
  vtkPolyData* output = vtkPolyData::GetData(outInfo, 0);
  const int ok = this->Superclass::RequestData(request, inInfo, outInfo);
  vtkOFB* ofb = vtkOFB::GetData(inInfo[1], 0);
  if (output)
  {
    vtkAbstractArray* mask = output->GetPointData()->GetAbstractArray(MaskName);
    if (ok && ofb && mask && output->GetNumberOfPoints() > 0)
    {
      output->GetInformation()->Set(OFB(), ofb);
      Registry().Add(mask, ofb);
    }
    else
    {
      output->GetInformation()->Remove(OFB());
    }
  }
  return ok;
}

//------------------------------------------------------------------------------
void vtkOFBParaViewProbe::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
}
