//! Terrain displacement PSD models, two-track synthesis with coherence, spectral estimators (Chapter 2.2.2).
