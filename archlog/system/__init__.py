"""Linking: one system configuration's node instances, with the summaries, models and configured ports they run."""
