"""Extractors: workspace, launch files, C++ and Python sources, message files, node models."""
