"""Task panels (GUI only): step through the cuts, train a policy."""
