"""Ad-hoc queries, explanations and the interactive REPL over the same facts and rules."""
