"""Analysis of a run of examples/tidal_shear (Damsgaard et al. 2016, GRL): the package's own
estimators (cycles) and the original program's, sphere's, as its scripts define the paper's
numbers (original). `python3 -m porewater_analysis RUN_DIR` compares them on a run folder."""
