"""View providers (GUI only)."""
