"""Commands kept in their own modules (registered in tmm_cli/cli.py); each imports its core lazily."""
