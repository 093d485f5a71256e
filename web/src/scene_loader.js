// Turns the server's binary glTF into three.js objects lit as lpfg lights them:
// its PBR materials become Lambert (diffuse colour, two-sided) and its lines
// plain coloured lines. Colours stay the sRGB values lpfg puts on screen.
import * as THREE from 'three';
import { GLTFLoader } from 'three/examples/jsm/loaders/GLTFLoader.js';
import { parseInstances } from './instances.js';
import { surfaceMaterial } from './materials.js';

const loader = new GLTFLoader();

function srgbColor(linearColor) {
  return linearColor.clone().convertLinearToSRGB();
}

function lpfgMaterial(source, isLine, renderMode) {
  const color = source.color ? srgbColor(source.color) : new THREE.Color(1, 1, 1);
  const common = {
    color,
    transparent: source.transparent || source.opacity < 1,
    opacity: source.opacity,
    vertexColors: source.vertexColors,
  };
  if (isLine) return new THREE.LineBasicMaterial(common);
  const map = source.map;
  // Texels are used as they are stored, as OpenGL's modulate does.
  if (map) map.colorSpace = THREE.NoColorSpace;
  return surfaceMaterial(renderMode, {
    ...common,
    map,
    side: THREE.DoubleSide,
    emissive: source.emissive ? srgbColor(source.emissive) : new THREE.Color(0, 0, 0),
    alphaTest: source.alphaTest,
  });
}

// {root: Object3D, parser, bounds: Sphere, primitives: [Mesh|LineSegments|InstancedMesh]}
// `instances`: the big scene's instanced spheres and cylinders, or null;
// `renderMode`: the view file's (state.view.render_mode).
export async function parseScene(buffer, instances = null, renderMode = 'shaded') {
  const gltf = await loader.parseAsync(buffer, '');
  const root = gltf.scene;
  const primitives = [];
  let instanced = null;
  if (instances) {
    instanced = parseInstances(instances, renderMode);
    root.add(instanced, instanced.userData.proxy);
    primitives.push(...instanced.children);
  }
  const proxy = instanced?.userData.proxy;
  root.traverse((object) => {
    if (object.isInstancedMesh || object.parent === proxy || (!object.isMesh && !object.isLine && !object.isPoints))
      return;
    const old = object.material;
    object.material = lpfgMaterial(old, object.isLine || object.isPoints, renderMode);
    old.dispose();
    object.matrixAutoUpdate = false;
    primitives.push(object);
  });
  root.updateMatrixWorld(true);
  const box = new THREE.Box3().setFromObject(root);
  const bounds = box.isEmpty() ? new THREE.Sphere(new THREE.Vector3(), 1) : box.getBoundingSphere(new THREE.Sphere());
  return { root, parser: gltf.parser, bounds, primitives, instanced };
}

export function disposeScene(scene) {
  if (!scene) return;
  scene.root.traverse((object) => {
    object.geometry?.dispose();
    const materials = Array.isArray(object.material) ? object.material : [object.material];
    for (const material of materials) {
      if (!material) continue;
      material.map?.dispose();
      material.dispose();
    }
  });
  scene.root.removeFromParent();
}
