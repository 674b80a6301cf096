#!/usr/bin/env python3
"""Serves a folder (build-web/) on 127.0.0.1 with the headers that make the page cross-origin
isolated (Cross-Origin-Opener-Policy and Cross-Origin-Embedder-Policy), which browsers require
before they give a page SharedArrayBuffer, and so threads. Usage: serve.py FOLDER [PORT]."""
import functools
import http.server
import sys


class IsolatedHandler(http.server.SimpleHTTPRequestHandler):
    extensions_map = {**http.server.SimpleHTTPRequestHandler.extensions_map, ".wasm": "application/wasm"}

    def end_headers(self):
        self.send_header("Cross-Origin-Opener-Policy", "same-origin")
        self.send_header("Cross-Origin-Embedder-Policy", "require-corp")
        self.send_header("Cache-Control", "no-cache")
        super().end_headers()


def main():
    if len(sys.argv) < 2:
        sys.exit("usage: serve.py FOLDER [PORT]")
    port = int(sys.argv[2]) if len(sys.argv) > 2 else 8000
    handler = functools.partial(IsolatedHandler, directory=sys.argv[1])
    with http.server.ThreadingHTTPServer(("127.0.0.1", port), handler) as server:
        print(f"serving {sys.argv[1]} on http://127.0.0.1:{port}/luz.html (Ctrl+C stops)", flush=True)
        server.serve_forever()


if __name__ == "__main__":
    main()
