"""The DIN 66025 NC kernel shared by every dialect: blocks, modal state, arcs, canon interface."""
