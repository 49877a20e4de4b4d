"""Datalog rules: rule files with metadata, and the clingo-based engine that runs them."""
