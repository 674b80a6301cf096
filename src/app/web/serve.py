#!/usr/bin/env python3
"""Serves a folder (build-web/) on 127.0.0.1 with the headers that make the page cross-origin
isolated (Cross-Origin-Opener-Policy and Cross-Origin-Embedder-Policy), which browsers require
before they give a page SharedArrayBuffer, and so threads. With --no-isolation it sends neither,
as a static host that cannot send headers would: the page's service worker then provides them.
Usage: serve.py FOLDER [PORT] [--no-isolation]."""
import functools
import http.server
import sys


class PageHandler(http.server.SimpleHTTPRequestHandler):
    extensions_map = {**http.server.SimpleHTTPRequestHandler.extensions_map,
                      ".wasm": "application/wasm", ".js": "text/javascript"}

    def __init__(self, *args, isolated=True, **kwargs):
        self.isolated = isolated
        super().__init__(*args, **kwargs)

    def end_headers(self):
        if self.isolated:
            self.send_header("Cross-Origin-Opener-Policy", "same-origin")
            self.send_header("Cross-Origin-Embedder-Policy", "require-corp")
        self.send_header("Cache-Control", "no-cache")
        super().end_headers()


def main():
    flags = [a for a in sys.argv[1:] if a.startswith("--")]
    args = [a for a in sys.argv[1:] if not a.startswith("--")]
    if not args or set(flags) - {"--no-isolation"}:
        sys.exit("usage: serve.py FOLDER [PORT] [--no-isolation]")
    port = int(args[1]) if len(args) > 1 else 8000
    isolated = "--no-isolation" not in flags
    handler = functools.partial(PageHandler, directory=args[0], isolated=isolated)
    with http.server.ThreadingHTTPServer(("127.0.0.1", port), handler) as server:
        how = "cross-origin isolated" if isolated else "without isolation headers"
        print(f"serving {args[0]} on http://127.0.0.1:{port}/luz.html, {how} (Ctrl+C stops)", flush=True)
        server.serve_forever()


if __name__ == "__main__":
    main()
