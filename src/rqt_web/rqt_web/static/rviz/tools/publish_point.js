// Publish Point: a click publishes the point of the robot or a marker under the mouse, else
// of the ground plane; then back to Interact, as rviz2.
export function create({pickable}, {raycaster, aim, groundPoint, publish, setTool}) {
  return {point: (event) => {
    aim(event);
    const hit = raycaster.intersectObjects(pickable, true).find((h) => h.object.isMesh);
    const at = hit ? hit.point : groundPoint(event);
    if (at) publish('point', at, 0);
    setTool('interact');
  }};
}
