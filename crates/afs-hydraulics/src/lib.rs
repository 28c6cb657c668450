//! Hydraulic articulated frame steering: strut kinematics, valve, continuity, torque (Chapters 3-4).
