"""The fixtures come from the ws_testing pytest plugin (src/ws_testing): this file only puts
tests/ on sys.path (pytest's default import mode adds a conftest's folder), so the tests of
tests/ and its subfolders import tests/'s helper modules (`from support import ...`)."""
