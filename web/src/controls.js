// The mouse as lpfg uses it (LPFG manual 1.2.1): left drag rotates about the
// screen's Y (horizontal motion) and X (vertical motion) axes through the
// target; Shift+left pans; Ctrl/Cmd+left or middle zooms (up = in);
// Shift+middle rolls about the view axis; the wheel zooms.
import * as THREE from 'three';

const ROTATE_PER_PIXEL = Math.PI / 360;
const ZOOM_PER_PIXEL = 0.005;
const CLICK_SLOP = 4;

function modeOf(event) {
  const command = event.ctrlKey || event.metaKey;
  if (event.button === 0) {
    if (command) return 'zoom';
    return event.shiftKey ? 'pan' : 'rotate';
  }
  if (event.button === 1) return event.shiftKey ? 'roll' : 'zoom';
  return null;
}

export class LpfgControls {
  // onClick(x, y) hears a press and release without motion (a pick).
  constructor(viewer, onClick) {
    this.viewer = viewer;
    this.onClick = onClick;
    this.drag = null;
    const canvas = viewer.canvas;
    canvas.addEventListener('pointerdown', (e) => this.down(e));
    canvas.addEventListener('pointermove', (e) => this.move(e));
    canvas.addEventListener('pointerup', (e) => this.up(e));
    canvas.addEventListener('pointercancel', () => {
      this.drag = null;
      this.viewer.setMoving(false);
    });
    canvas.addEventListener('wheel', (e) => this.wheel(e), { passive: false });
    canvas.addEventListener('contextmenu', (e) => e.preventDefault());
    // The middle button would start the browser's autoscroll.
    canvas.addEventListener('mousedown', (e) => { if (e.button === 1) e.preventDefault(); });
  }

  down(event) {
    const mode = modeOf(event);
    if (!mode) return;
    event.preventDefault();
    this.viewer.canvas.setPointerCapture(event.pointerId);
    this.drag = { mode, x: event.clientX, y: event.clientY, startX: event.clientX, startY: event.clientY, moved: false };
  }

  move(event) {
    const drag = this.drag;
    if (!drag) return;
    const dx = event.clientX - drag.x;
    const dy = event.clientY - drag.y;
    drag.x = event.clientX;
    drag.y = event.clientY;
    if (!drag.moved && Math.hypot(event.clientX - drag.startX, event.clientY - drag.startY) < CLICK_SLOP) return;
    drag.moved = true;
    this.viewer.setMoving(true);
    if (drag.mode === 'rotate') this.rotate(dx, dy);
    else if (drag.mode === 'pan') this.pan(dx, dy);
    else if (drag.mode === 'zoom') this.zoom(dy);
    else if (drag.mode === 'roll') this.roll(dx);
    this.viewer.userMoved = true;
    this.viewer.updateCamera();
  }

  up(event) {
    const drag = this.drag;
    this.drag = null;
    this.viewer.setMoving(false);
    if (drag && !drag.moved && drag.mode === 'rotate' && event.button === 0) {
      const rect = this.viewer.canvas.getBoundingClientRect();
      this.onClick(event.clientX - rect.left, event.clientY - rect.top);
    }
  }

  wheel(event) {
    event.preventDefault();
    const lines = event.deltaMode === 1 ? 16 : 1;
    this.zoom(Math.max(-200, Math.min(200, event.deltaY * lines)) * 0.5);
    this.viewer.userMoved = true;
    // Wheel turns come in bursts: the whole picture once they stop.
    this.viewer.setMoving(true);
    clearTimeout(this.wheelStill);
    this.wheelStill = setTimeout(() => this.viewer.setMoving(false), 250);
    this.viewer.updateCamera();
  }

  axes() {
    const { eye, target, up } = this.viewer.cam;
    const forward = target.clone().sub(eye).normalize();
    const right = forward.clone().cross(up).normalize();
    const trueUp = right.clone().cross(forward).normalize();
    return { forward, right, up: trueUp };
  }

  // Turning the model one way is turning the camera about the target the other way.
  rotate(dx, dy) {
    const cam = this.viewer.cam;
    const { right, up } = this.axes();
    const turn = new THREE.Quaternion().setFromAxisAngle(up, -dx * ROTATE_PER_PIXEL)
      .multiply(new THREE.Quaternion().setFromAxisAngle(right, -dy * ROTATE_PER_PIXEL));
    const offset = cam.eye.clone().sub(cam.target).applyQuaternion(turn);
    cam.eye.copy(cam.target).add(offset);
    cam.up.copy(up).applyQuaternion(turn);
  }

  // The model follows the mouse.
  pan(dx, dy) {
    const cam = this.viewer.cam;
    const { right, up } = this.axes();
    const scale = this.viewer.worldPerPixel();
    const shift = right.multiplyScalar(-dx * scale).add(up.multiplyScalar(dy * scale));
    cam.eye.add(shift);
    cam.target.add(shift);
  }

  // dy < 0 (upward) zooms in.
  zoom(dy) {
    const cam = this.viewer.cam;
    const factor = Math.exp(dy * ZOOM_PER_PIXEL);
    if (!cam.perspective) {
      cam.halfHeight = Math.max(1e-9, cam.halfHeight * factor);
      return;
    }
    const offset = cam.eye.clone().sub(cam.target);
    const length = Math.max(offset.length() * factor, 1e-6);
    cam.eye.copy(cam.target).add(offset.setLength(length));
  }

  // Moving right rolls the model clockwise.
  roll(dx) {
    const cam = this.viewer.cam;
    const { forward, up } = this.axes();
    cam.up.copy(up.applyAxisAngle(forward, -dx * ROTATE_PER_PIXEL));
  }
}
