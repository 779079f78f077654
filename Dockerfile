# slmp-sim in a container: docker build -t slmp-sim . && docker run -p 5000:5000 -p 5000:5000/udp slmp-sim
FROM debian:12 AS build
RUN apt-get update -qq && DEBIAN_FRONTEND=noninteractive apt-get install -y -qq \
      g++ cmake ninja-build libboost-dev libboost-program-options-dev nlohmann-json3-dev libspdlog-dev catch2 \
    && rm -rf /var/lib/apt/lists/*
WORKDIR /src
COPY . .
RUN cmake -S . -B build -G Ninja -DCMAKE_BUILD_TYPE=Release -DBUILD_TESTING=OFF && cmake --build build --target slmp-sim

FROM debian:12-slim
RUN apt-get update -qq && DEBIAN_FRONTEND=noninteractive apt-get install -y -qq \
      libboost-program-options1.74.0 libspdlog1.10 && rm -rf /var/lib/apt/lists/*
COPY --from=build /src/build/server/slmp-sim /usr/local/bin/slmp-sim
EXPOSE 5000/tcp 5000/udp
ENTRYPOINT ["slmp-sim"]
