"""The explanatory note: a typst template (package data) and the data it reads, compiled to PDF."""
