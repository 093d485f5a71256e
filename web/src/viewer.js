// The 3D view: renderer, camera from the view file, lights, and rendering on
// demand (a frame only when the camera, the scene or the canvas size changes).
import * as THREE from 'three';
import { showProxy } from './instances.js';
import { disposeScene } from './scene_loader.js';

// Colours are lpfg's sRGB values, shaded and shown as they are (as OpenGL does).
THREE.ColorManagement.enabled = false;

const v3 = (a, fallback) => (Array.isArray(a) && a.length >= 3 ? new THREE.Vector3(a[0], a[1], a[2]) : fallback.clone());
const rgb = (a, fallback = [1, 1, 1]) => new THREE.Color(...(Array.isArray(a) ? a : fallback));

// three's lights divide by pi (physically based); OpenGL's fixed pipeline does not.
const LIGHT_SCALE = Math.PI;
// A colour-map entry's ambient reflectance is a quarter of its colour, as in the PNG renderer.
const AMBIENT_REFLECTANCE = 0.25;

export class Viewer {
  constructor(canvas) {
    this.canvas = canvas;
    this.renderer = new THREE.WebGLRenderer({ canvas, antialias: true, preserveDrawingBuffer: true });
    this.renderer.outputColorSpace = THREE.LinearSRGBColorSpace;
    this.renderer.setPixelRatio(Math.min(window.devicePixelRatio || 1, 2));
    this.scene = new THREE.Scene();
    this.perspectiveCamera = new THREE.PerspectiveCamera(45, 1, 0.1, 1000);
    this.orthographicCamera = new THREE.OrthographicCamera(-1, 1, 1, -1, 0.1, 1000);
    this.scene.add(this.perspectiveCamera, this.orthographicCamera);
    this.lights = new THREE.Group();
    this.scene.add(this.lights);
    this.overlay = new THREE.Group();
    this.scene.add(this.overlay);
    // The camera as the controls move it; `home` is the view file's.
    this.cam = { eye: new THREE.Vector3(0, 0, 5), target: new THREE.Vector3(), up: new THREE.Vector3(0, 1, 0),
      perspective: true, fov: 45, halfHeight: 1 };
    this.home = null;
    // Until the user moves the camera it follows the server's framing (which
    // grows with the plant, as lpfg's does); afterwards it stays until Reset view.
    this.userMoved = false;
    this.model = null;
    this.framesRendered = 0;
    this.frameRequested = false;
    this.frameWaiters = [];
    new ResizeObserver(() => this.resize()).observe(canvas);
    this.resize();
  }

  get camera() {
    return this.cam.perspective ? this.perspectiveCamera : this.orthographicCamera;
  }

  resize() {
    const width = Math.max(1, this.canvas.clientWidth);
    const height = Math.max(1, this.canvas.clientHeight);
    this.renderer.setSize(width, height, false);
    this.updateCamera();
  }

  // Background, lights and the view file's camera from state.view; the camera
  // moves there unless the user has moved it.
  setView(view) {
    this.scene.background = rgb(view.background, [0, 0, 0]);
    this.setLights(view.lights, view.stationary_lights !== false);
    // lpfg lights only shaded models; filled ones show their flat colours.
    this.renderMode = view.render_mode || 'shaded';
    const eye = v3(view.eye, new THREE.Vector3(0, 0, 5));
    const target = v3(view.target, new THREE.Vector3());
    const fov = view.fov || 45;
    // A flat model is shown orthographic, framed as the perspective view would frame it.
    const halfHeight = view.ortho_half_height || eye.distanceTo(target) * Math.tan(THREE.MathUtils.degToRad(fov) / 2) || 1;
    this.home = { eye, target, up: v3(view.up, new THREE.Vector3(0, 1, 0)),
      perspective: view.perspective !== false && !view.two_d, fov, halfHeight };
    if (!this.userMoved) this.resetView();
    else this.requestRender();
  }

  resetView() {
    this.userMoved = false;
    if (!this.home) return;
    const h = this.home;
    Object.assign(this.cam, { eye: h.eye.clone(), target: h.target.clone(), up: h.up.clone(),
      perspective: h.perspective, fov: h.fov, halfHeight: h.halfHeight });
    this.updateCamera();
  }

  // Lights fixed in the scene (lpfg's default) or, when not stationary, moving with the camera.
  setLights(lights, stationary) {
    for (const light of [...this.lights.children, ...this.perspectiveCamera.children, ...this.orthographicCamera.children]) {
      light.removeFromParent();
      light.dispose?.();
    }
    const ambient = new THREE.Color(0, 0, 0);
    const given = lights || [];
    if (given.length === 0) {
      // A headlight: lights whatever side the user turns to the camera.
      ambient.setRGB(AMBIENT_REFLECTANCE, AMBIENT_REFLECTANCE, AMBIENT_REFLECTANCE);
      for (const camera of [this.perspectiveCamera, this.orthographicCamera]) {
        const light = new THREE.DirectionalLight(0xffffff, LIGHT_SCALE);
        light.position.set(0, 0, 1);
        light.target.position.set(0, 0, 0);
        camera.add(light, light.target);
      }
    }
    for (const l of given) {
      ambient.add(rgb(l.ambient).multiplyScalar(AMBIENT_REFLECTANCE));
      const directional = l.kind === 'directional' || !l.position;
      const make = () => {
        const light = directional
          ? new THREE.DirectionalLight(rgb(l.diffuse), LIGHT_SCALE)
          : new THREE.PointLight(rgb(l.diffuse), LIGHT_SCALE, 0, 0);
        light.position.copy(v3(directional ? l.direction : l.position, new THREE.Vector3(0, 0, 1)));
        return light;
      };
      if (stationary) {
        const light = make();
        this.lights.add(light);
        if (light.target) this.lights.add(light.target);
      } else {
        for (const camera of [this.perspectiveCamera, this.orthographicCamera]) {
          const light = make();
          camera.add(light);
          if (light.target) camera.add(light.target);
        }
      }
    }
    this.lights.add(new THREE.AmbientLight(ambient, LIGHT_SCALE));
    this.requestRender();
  }

  // While the camera moves, a big scene's instances are drawn as their proxy
  // (instances.js); the whole picture when it stops.
  setMoving(moving) {
    if (moving === this.moving) return;
    this.moving = moving;
    if (this.model?.instanced) {
      showProxy(this.model.instanced, moving);
      this.requestRender();
    }
  }

  // Replaces the model's objects (the old ones are freed).
  setModel(model) {
    const old = this.model;
    this.model = model;
    if (model?.instanced) showProxy(model.instanced, Boolean(this.moving));
    if (model) this.scene.add(model.root);
    disposeScene(old);
    this.updateCamera();
  }

  // World units per screen pixel at the target's depth.
  worldPerPixel() {
    const height = Math.max(1, this.canvas.clientHeight);
    if (!this.cam.perspective) return (2 * this.cam.halfHeight) / height;
    const distance = this.cam.eye.distanceTo(this.cam.target);
    return (2 * distance * Math.tan(THREE.MathUtils.degToRad(this.cam.fov) / 2)) / height;
  }

  updateCamera() {
    const { eye, target, up } = this.cam;
    const aspect = Math.max(1, this.canvas.clientWidth) / Math.max(1, this.canvas.clientHeight);
    const camera = this.camera;
    camera.position.copy(eye);
    camera.up.copy(up);
    camera.lookAt(target);
    // Clip planes around the model wherever the camera has been moved to.
    const bounds = this.model?.bounds;
    const distance = bounds ? eye.distanceTo(bounds.center) : eye.distanceTo(target);
    const radius = bounds ? bounds.radius * 1.05 + 1e-6 : Math.max(1, distance);
    const far = distance + radius;
    if (this.cam.perspective) {
      camera.fov = this.cam.fov;
      camera.aspect = aspect;
      camera.near = Math.max(distance - radius, far * 1e-4);
    } else {
      const h = this.cam.halfHeight;
      Object.assign(camera, { left: -h * aspect, right: h * aspect, top: h, bottom: -h });
      camera.near = distance - radius;
    }
    camera.far = far;
    camera.updateProjectionMatrix();
    camera.updateMatrixWorld(true);
    this.requestRender();
  }

  requestRender() {
    if (this.frameRequested) return;
    this.frameRequested = true;
    requestAnimationFrame(() => this.renderNow());
  }

  renderNow() {
    this.frameRequested = false;
    this.renderer.render(this.scene, this.camera);
    this.framesRendered++;
    const waiters = this.frameWaiters;
    this.frameWaiters = [];
    for (const resolve of waiters) resolve();
  }

  // Resolves once the next frame is drawn.
  nextFrame() {
    return new Promise((resolve) => {
      this.frameWaiters.push(resolve);
      this.requestRender();
    });
  }

  // Objects of the model under a canvas point (CSS pixels), nearest first.
  pick(x, y) {
    if (!this.model) return [];
    const ndc = new THREE.Vector2((x / this.canvas.clientWidth) * 2 - 1, -(y / this.canvas.clientHeight) * 2 + 1);
    const raycaster = new THREE.Raycaster();
    raycaster.params.Line.threshold = this.worldPerPixel() * 4;
    raycaster.params.Points.threshold = this.worldPerPixel() * 4;
    raycaster.setFromCamera(ndc, this.camera);
    return raycaster.intersectObjects(this.model.primitives, false);
  }

  snapshot() {
    this.renderNow();
    return this.canvas.toDataURL('image/png');
  }
}
