//! ISO 2631-1 weightings and exposure, roll (LTR, SP-DRT) and yaw/steering measures.
