// The server's HTTP API (studio_api.md): relative URLs, JSON in and out.

async function answer(response) {
  const text = await response.text();
  let body = null;
  try {
    body = text ? JSON.parse(text) : null;
  } catch {
    body = { error: text };
  }
  if (!response.ok) throw new Error(body?.error || `${response.status} ${response.statusText}`);
  return body;
}

export async function getJSON(path, query = {}) {
  const params = new URLSearchParams();
  for (const [k, v] of Object.entries(query)) if (v != null && v !== '') params.set(k, v);
  const qs = params.toString();
  return answer(await fetch(qs ? `${path}?${qs}` : path, { cache: 'no-store' }));
}

export async function postJSON(path, body) {
  return answer(await fetch(path, {
    method: 'POST',
    headers: { 'Content-Type': 'application/json' },
    body: body === undefined ? '' : JSON.stringify(body),
  }));
}

// The instances of a big picture's spheres and cylinders (src/studio/scene_instances.h):
// an ArrayBuffer, or null when the picture has none.
export async function getInstances(viewId) {
  const response = await fetch(`/api/scene-instances.bin?view=${viewId}`, { cache: 'no-store' });
  if (response.status === 204) return null;
  if (!response.ok) throw new Error(`scene instances: ${response.status} ${response.statusText}`);
  return response.arrayBuffer();
}

// The binary glTF of the current picture: {buffer, version}, or null when there is none yet.
export async function getScene(viewId) {
  const response = await fetch(`/api/scene.glb?view=${viewId}`, { cache: 'no-store' });
  if (response.status === 204) return null;
  if (!response.ok) throw new Error(`scene: ${response.status} ${response.statusText}`);
  const version = Number(response.headers.get('X-Sylva-Scene-Version'));
  return { buffer: await response.arrayBuffer(), version: Number.isFinite(version) ? version : null };
}
