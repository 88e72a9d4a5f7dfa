"""Canon sinks: what the machine would do, recorded, written, drawn and checked."""
