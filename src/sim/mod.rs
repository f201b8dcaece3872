//! PLACEHOLDER (sim work): the simulated machine.
