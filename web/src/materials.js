// Materials as lpfg draws surfaces.
import * as THREE from 'three';

// A surface material as the view file's render mode draws it: lit when
// shaded (or with shadows), flat colour when filled, edges when wireframe.
export function surfaceMaterial(renderMode, parameters) {
  if (renderMode === 'shaded' || renderMode === 'shadows') return new THREE.MeshLambertMaterial(parameters);
  const { emissive, ...flat } = parameters;
  return new THREE.MeshBasicMaterial({ ...flat, wireframe: renderMode === 'wireframe' });
}
