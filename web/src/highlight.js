// Marks a module's elements over the model: an overlay drawing the same
// buffers (same attributes and indices, a narrower draw range) in one colour
// through everything in front of it.
import * as THREE from 'three';
import { elementSize } from './provenance.js';

const COLOR = 0xffb020;

export class Highlight {
  constructor(viewer) {
    this.viewer = viewer;
    this.meshMaterial = new THREE.MeshBasicMaterial({ color: COLOR, side: THREE.DoubleSide, depthTest: false,
      transparent: true, opacity: 0.8 });
    this.lineMaterial = new THREE.LineBasicMaterial({ color: COLOR, depthTest: false, transparent: true });
  }

  clear() {
    // The overlay's geometries share the model's buffers: disposing them would
    // free those, so they are only dropped.
    this.viewer.overlay.clear();
    this.viewer.requestRender();
  }

  show(ranges) {
    this.viewer.overlay.clear();
    for (const { primitive, first, count, instance } of ranges) {
      if (instance !== undefined) {
        // One instance: its shape where the instance is.
        const mark = new THREE.Mesh(primitive.geometry, this.meshMaterial);
        mark.matrixAutoUpdate = false;
        primitive.getMatrixAt(instance, mark.matrix);
        mark.matrix.premultiply(primitive.matrixWorld);
        mark.renderOrder = 10;
        this.viewer.overlay.add(mark);
        continue;
      }
      const source = primitive.geometry;
      const geometry = new THREE.BufferGeometry();
      for (const [name, attribute] of Object.entries(source.attributes)) geometry.setAttribute(name, attribute);
      if (source.index) geometry.setIndex(source.index);
      const size = elementSize(primitive);
      geometry.setDrawRange(first * size, count * size);
      const mark = primitive.isMesh
        ? new THREE.Mesh(geometry, this.meshMaterial)
        : primitive.isLineSegments
          ? new THREE.LineSegments(geometry, this.lineMaterial)
          : new THREE.Line(geometry, this.lineMaterial);
      mark.matrixAutoUpdate = false;
      mark.matrix.copy(primitive.matrixWorld);
      mark.renderOrder = 10;
      this.viewer.overlay.add(mark);
    }
    this.viewer.requestRender();
  }
}
