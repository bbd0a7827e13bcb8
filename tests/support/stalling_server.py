#!/usr/bin/env python3
"""A hostile HTTP server on 127.0.0.1 for the deadline tests: it accepts every connection and
then misbehaves in one way, and stops by itself after --lifetime seconds.

  stalling_server.py MODE --port-file FILE [--lifetime SECONDS]

MODE:
  silent  reads the request and never answers (headers never come)
  huge    answers 200 with Content-Length: 10^12 and then sends nothing
  trickle answers 200 with Content-Length: 10^6 and then one byte a second

The port it listens on is written to FILE once it listens (a temporary name, then renamed).
"""
import argparse
import os
import socket
import threading
import time

ANSWERS = {
    "silent": None,
    "huge": b"HTTP/1.1 200 OK\r\nContent-Length: 1000000000000\r\n\r\n",
    "trickle": b"HTTP/1.1 200 OK\r\nContent-Length: 1000000\r\n\r\n",
}


def serve(connection, mode, deadline):
    with connection:
        connection.settimeout(1.0)
        try:
            connection.recv(65536)  # the request (its bytes are not needed)
            if ANSWERS[mode]:
                connection.sendall(ANSWERS[mode])
            while time.monotonic() < deadline:
                if mode == "trickle":
                    connection.sendall(b"x")
                time.sleep(1.0)
        except OSError:
            pass  # the client gave up: what the tests want


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("mode", choices=sorted(ANSWERS))
    parser.add_argument("--port-file", required=True)
    parser.add_argument("--lifetime", type=float, default=60.0)
    args = parser.parse_args()
    deadline = time.monotonic() + args.lifetime
    listener = socket.socket(socket.AF_INET, socket.SOCK_STREAM)
    listener.setsockopt(socket.SOL_SOCKET, socket.SO_REUSEADDR, 1)
    listener.bind(("127.0.0.1", 0))
    listener.listen(64)
    listener.settimeout(0.5)
    with open(args.port_file + ".tmp", "w", encoding="ascii") as out:
        out.write(str(listener.getsockname()[1]))
    os.rename(args.port_file + ".tmp", args.port_file)
    while time.monotonic() < deadline:
        try:
            connection, _ = listener.accept()
        except socket.timeout:
            continue
        threading.Thread(target=serve, args=(connection, args.mode, deadline), daemon=True).start()
    listener.close()


if __name__ == "__main__":
    main()
