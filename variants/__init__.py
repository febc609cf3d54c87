"""Table 1.2 data, shipped inside the package as ``tmm_cli.data`` (see pyproject.toml)."""
