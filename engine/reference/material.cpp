#include "reference/brdf_reference.h"

namespace raylab::reference {

Material fromRecord(const gpu::MaterialRecord& record) {
  Material material;
  material.model = record.model;
  material.rhoD = dvec3(record.rhoD);
  material.rhoS = dvec3(record.rhoS);
  material.tint = dvec3(record.tint);
  material.delta = record.delta;
  material.eta = record.eta;
  material.s = record.s;
  material.m = record.m;
  material.alphaX = record.alphaX;
  material.alphaY = record.alphaY;
  material.nu = record.nu;
  material.nv = record.nv;
  return material;
}

}  // namespace raylab::reference
