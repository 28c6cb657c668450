//! Hydro-pneumatic suspension strut with gas-oil emulsion (Chapter 5).
