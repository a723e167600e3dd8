#include "vtkSmoothShrinkIndexFeatures.h"

#include "vtkObjectFactory.h"

vtkStandardNewMacro(vtkSmoothShrinkIndexFeatures);

vtkSmoothShrinkIndexFeatures::vtkSmoothShrinkIndexFeatures()
{
  this->Alpha = 1.0;
  this->UseVoxelFilter = false;
  this->SSICenter = POINT;
}

vtkSmoothShrinkIndexFeatures::~vtkSmoothShrinkIndexFeatures() = default;
