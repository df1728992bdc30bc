// Placeholder so this branch builds on its own; the real CLI lives on main.
// On merge, keep main's version of this file.
int main() { return 0; }
