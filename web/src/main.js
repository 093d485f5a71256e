import * as THREE from 'three';

const canvas = document.getElementById('view');
const renderer = new THREE.WebGLRenderer({ canvas, antialias: true, preserveDrawingBuffer: true });
renderer.setSize(canvas.clientWidth, canvas.clientHeight, false);
renderer.render(new THREE.Scene(), new THREE.PerspectiveCamera());
