// The page's state, shared by every module. window.rviz exposes it for tests: frames,
// per-display status, model links, clouds and images received, markers drawn, the active
// tool and what the tools published.
export const params = new URLSearchParams(location.search);

export const state = {fixedFrame: params.get('fixed_frame') || 'map', background: [48, 48, 48],
  displays: [], frames: {}, status: {}, links: [], ready: false, renders: 0, config: null,
  clouds: {}, images: {}, maps: {}, particles: {}, nav2: null, markers: [], meshes: [], tool: 'interact', published: []};
window.rviz = state;

// The enabled displays of a class (by its last part: '/Grid' matches rviz_default_plugins/Grid).
export const enabled = (cls) => state.displays.filter((d) => d.enabled && d.class.endsWith(cls));
