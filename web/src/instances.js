// A big scene's spheres and cylinders, sent as instances (the binary form of
// src/studio/scene_instances.h): one InstancedMesh per shape and colour, so a
// plant of a million modules is a handful of draw calls. A cylinder instance
// is a cone frustum: the unit cylinder (y from 0 to 1) placed and scaled to
// its mean radius by its matrix, each end's radius (relative to the mean)
// from a per-instance attribute.
import * as THREE from 'three';
import { surfaceMaterial } from './materials.js';

const MAGIC = 0x494c5953; // "SYLI"
const SPHERE = 0;
const CYLINDER = 1;

function unitSphere(slices) {
  return new THREE.SphereGeometry(1, slices, Math.max(2, Math.ceil(slices / 2)));
}

function unitCylinder(sides) {
  const geometry = new THREE.CylinderGeometry(1, 1, 1, sides, 1, true);
  geometry.translate(0, 0.5, 0);
  return geometry;
}

// The frustum's radius along the cylinder: r0 at y = 0, r1 at y = 1.
function frustumMaterial(renderMode, parameters) {
  const material = surfaceMaterial(renderMode, parameters);
  material.onBeforeCompile = (shader) => {
    shader.vertexShader = shader.vertexShader
      .replace('#include <common>', '#include <common>\nattribute vec2 radii;')
      .replace('#include <begin_vertex>',
        '#include <begin_vertex>\ntransformed.xz *= mix(radii.x, radii.y, position.y);');
  };
  material.customProgramCacheKey = () => `sylva-frustum-${renderMode}`;
  return material;
}

const up = new THREE.Vector3(0, 1, 0);

// What is drawn while the camera moves: each cylinder as a line from end to
// end and each sphere as a point, a few bytes per instance instead of dozens
// of triangles, so even a million modules turn smoothly; the shapes come back
// when the camera stops.
function proxyOf(shape, values, count, color) {
  const stride = shape === SPHERE ? 4 : 8;
  const positions = new Float32Array(count * (shape === SPHERE ? 3 : 6));
  for (let i = 0; i < count; ++i) {
    const v = i * stride;
    if (shape === SPHERE) positions.set(values.subarray(v, v + 3), i * 3);
    else positions.set(values.subarray(v, v + 6), i * 6);
  }
  const geometry = new THREE.BufferGeometry();
  geometry.setAttribute('position', new THREE.BufferAttribute(positions, 3));
  const proxy = shape === SPHERE
    ? new THREE.Points(geometry, new THREE.PointsMaterial({ color, size: 3, sizeAttenuation: false }))
    : new THREE.LineSegments(geometry, new THREE.LineBasicMaterial({ color }));
  proxy.matrixAutoUpdate = false;
  proxy.frustumCulled = false;
  return proxy;
}

// The instances in `buffer` (an ArrayBuffer) as a Group of InstancedMesh, each
// with userData.moduleIndices / moduleIds (Uint32Array, by instance id), and
// the group's userData.proxy (a Group, hidden) to draw while the camera moves.
export function parseInstances(buffer, renderMode = 'shaded') {
  const u32 = new Uint32Array(buffer);
  const f32 = new Float32Array(buffer);
  if (u32.length < 3 || u32[0] !== MAGIC) throw new Error('not a Sylva instances file');
  const group = new THREE.Group();
  const proxy = new THREE.Group();
  proxy.visible = false;
  group.userData.proxy = proxy;
  let at = 3;
  const matrix = new THREE.Matrix4();
  const position = new THREE.Vector3();
  const direction = new THREE.Vector3();
  const rotation = new THREE.Quaternion();
  const scale = new THREE.Vector3();
  for (let g = 0; g < u32[2]; ++g) {
    const shape = u32[at];
    const count = u32[at + 1];
    const slices = Math.max(3, u32[at + 2]);
    const color = new THREE.Color(f32[at + 3], f32[at + 4], f32[at + 5]);
    const opacity = f32[at + 6];
    at += 7;
    const stride = shape === SPHERE ? 4 : 8;
    const values = f32.subarray(at, at + count * stride);
    at += count * stride;
    const parameters = { color, side: THREE.DoubleSide, transparent: opacity < 1, opacity };
    let mesh;
    if (shape === SPHERE) {
      mesh = new THREE.InstancedMesh(unitSphere(slices), surfaceMaterial(renderMode, parameters), count);
      for (let i = 0; i < count; ++i) {
        const r = values[i * 4 + 3];
        matrix.makeScale(r, r, r).setPosition(values[i * 4], values[i * 4 + 1], values[i * 4 + 2]);
        mesh.setMatrixAt(i, matrix);
      }
    } else if (shape === CYLINDER) {
      const geometry = unitCylinder(slices);
      const radii = new Float32Array(count * 2);
      mesh = new THREE.InstancedMesh(geometry, frustumMaterial(renderMode, parameters), count);
      for (let i = 0; i < count; ++i) {
        const v = i * 8;
        position.set(values[v], values[v + 1], values[v + 2]);
        direction.set(values[v + 3] - values[v], values[v + 4] - values[v + 1], values[v + 5] - values[v + 2]);
        const length = direction.length();
        if (length > 0) rotation.setFromUnitVectors(up, direction.divideScalar(length));
        else rotation.identity();
        // The mean radius in the matrix (what picking and bounds see), the
        // ends' radii relative to it for the shader.
        const mean = (values[v + 6] + values[v + 7]) / 2;
        scale.set(mean, length, mean);
        matrix.compose(position, rotation, scale);
        mesh.setMatrixAt(i, matrix);
        radii[i * 2] = mean > 0 ? values[v + 6] / mean : 1;
        radii[i * 2 + 1] = mean > 0 ? values[v + 7] / mean : 1;
      }
      geometry.setAttribute('radii', new THREE.InstancedBufferAttribute(radii, 2));
    } else {
      throw new Error(`unknown instanced shape ${shape}`);
    }
    proxy.add(proxyOf(shape, values, count, color));
    mesh.userData.moduleIndices = u32.subarray(at, at + count);
    mesh.userData.moduleIds = u32.subarray(at + count, at + 2 * count);
    at += 2 * count;
    mesh.instanceMatrix.needsUpdate = true;
    mesh.computeBoundingSphere();
    mesh.computeBoundingBox?.();
    mesh.matrixAutoUpdate = false;
    group.add(mesh);
  }
  return group;
}

// Shows the proxy instead of the shapes (or back).
export function showProxy(group, moving) {
  group.userData.proxy.visible = moving;
  for (const mesh of group.children) mesh.visible = !moving;
}
