"""`python -m tmm_cli`: the same as the `tmm` command."""

from tmm_cli.cli import main

main()
