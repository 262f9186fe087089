'use strict';
// RViz: a 3D view of tf2 frames and the robot model, as rviz2 draws them (Z up, fixed frame
// at the origin). The page shell loads each page as a classic script; this one only loads the
// page's ES modules (static/rviz/, entry main.js), which import three.js (npm, served from
// /vendor) by name through the import map added here first.
(() => {
  const map = document.createElement('script');
  map.type = 'importmap';
  map.textContent = JSON.stringify({imports: {three: '/vendor/three.module.js'}});
  document.head.append(map);
  const entry = document.createElement('script');
  entry.type = 'module';
  entry.src = '/static/rviz/main.js';
  document.body.append(entry);
})();
