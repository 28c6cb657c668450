//! Vehicle models of articulated frame-steered vehicles (yaw-plane now, 3-D later).
