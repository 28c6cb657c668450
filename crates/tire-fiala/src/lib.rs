//! Fiala off-road tire: handling forces, relaxation, vertical contact and terrain enveloping.
