# slmp-sim in a container: docker build -t slmp-sim . && docker run -p 5000:5000 -p 5000:5000/udp -p 8080:8080 slmp-sim
# The same image as deploy/image/build.sh (which needs no Docker): the runtime
# packages of deploy/image/runtime-packages.txt, user 10001, the same entrypoint,
# command, ports and files. tests/deploy/ keeps the two in step (docs/deploy.md).
FROM debian:12 AS build
RUN apt-get update -qq && DEBIAN_FRONTEND=noninteractive apt-get install -y -qq \
      g++ cmake ninja-build libboost-dev libboost-program-options-dev nlohmann-json3-dev libspdlog-dev catch2 npm \
    && rm -rf /var/lib/apt/lists/*
WORKDIR /src
COPY . .
# uPlot, which the web monitor embeds (pinned by control/web-deps/package-lock.json).
RUN cd control/web-deps && npm ci --no-audit --no-fund --loglevel=error
RUN cmake -S . -B build -G Ninja -DCMAKE_BUILD_TYPE=Release -DBUILD_TESTING=OFF && cmake --build build --target slmp-sim

FROM debian:12-slim
COPY deploy/image/runtime-packages.txt /tmp/runtime-packages.txt
RUN apt-get update -qq \
    && grep -v -e '^[[:space:]]*#' -e '^[[:space:]]*$' /tmp/runtime-packages.txt \
       | DEBIAN_FRONTEND=noninteractive xargs apt-get install -y -qq --no-install-recommends \
    && rm -rf /var/lib/apt/lists/* /tmp/runtime-packages.txt
RUN useradd --uid 10001 --user-group --home-dir /var/lib/slmp-sim --no-create-home --shell /usr/sbin/nologin slmp-sim \
    && install -d -o 10001 -g 10001 -m 0750 /var/lib/slmp-sim
COPY --from=build /src/build/server/slmp-sim /usr/local/bin/slmp-sim
COPY deploy/image/healthcheck.sh /usr/local/bin/slmp-sim-healthcheck
COPY deploy/image/config.json /etc/slmp-sim/config.json
COPY examples/ /usr/share/slmp-sim/examples/
LABEL org.opencontainers.image.title="slmp-sim" \
      org.opencontainers.image.description="MELSEC PLC simulator (SLMP over TCP/UDP, HTTP API, web monitor)"
USER 10001:10001
WORKDIR /var/lib/slmp-sim
EXPOSE 5000/tcp 5000/udp 8080/tcp
# The image has no curl: slmp-sim-healthcheck is bash's /dev/tcp doing one GET
# (deploy/image/healthcheck.sh). With another HTTP port: SLMP_SIM_HTTP_PORT.
HEALTHCHECK --interval=10s --timeout=5s --start-period=10s --retries=3 CMD ["slmp-sim-healthcheck", "/healthz"]
STOPSIGNAL SIGTERM
ENTRYPOINT ["slmp-sim"]
CMD ["--config", "/etc/slmp-sim/config.json"]
