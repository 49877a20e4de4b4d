"""The recovered architecture as typed relations."""
