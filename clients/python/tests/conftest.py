# The kit's own suite runs against the real binary (SLMP_SIM_BINARY, set by CTest).
pytest_plugins = ["slmp_sim.pytest_plugin"]
