"""HTML pages: group.html, the group at a glance (self-contained, no network)."""
