"""The workspace: its packages, their executables (from CMake, setup files, plugin XML) and message definitions."""
