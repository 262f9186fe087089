'use strict';
// The start page: what each tool does, as rqt's Plugins menu would list them.
(() => {
  const main = document.getElementById('main');
  const tools = [
    ['/graph', 'Node Graph', 'nodes and topics, live (rqt_graph)'],
    ['/services', 'Service Caller', 'call a service from a form (rqt_service_caller)'],
    ['/topics', 'Topics', 'types, rates, latest messages, publish (rqt_topic)'],
    ['/parameters', 'Parameters', 'get and set parameters (rqt_reconfigure)'],
    ['/console', 'Console', '/rosout with filters (rqt_console)'],
    ['/actions', 'Actions', 'send goals, see feedback and results'],
    ['/turtlesim', 'Turtlesim', 'the live canvas, keyboard teleop'],
    ['/tf_tree', 'TF Tree', 'the tf2 frames, live, with rates and times (rqt_tf_tree)'],
    ['/foxglove', 'Foxglove', 'connect Foxglove or Lichtblick (foxglove_bridge)'],
    ['/rviz', 'RViz', 'the robot model and tf2 frames in 3D (rviz2)'],
    ['/joint_state_publisher', 'Joint State Publisher', 'a slider per movable joint (joint_state_publisher_gui)'],
  ];
  const list = rqt.el('ul');
  for (const [href, name, what] of tools) {
    list.append(rqt.el('li', {}, rqt.el('a', {href, text: name}), ` - ${what}`));
  }
  main.append(rqt.el('h1', {text: 'rqt in the browser'}), list);
})();
