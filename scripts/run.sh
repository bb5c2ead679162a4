#!/usr/bin/env bash
# Starts the classroom simulator on Linux: installs Mono and libgdiplus from the distribution when
# they are missing, builds the app (net48) and runs it under Mono. Arguments go to the app.
set -euo pipefail
cd "$(dirname "$0")/.."

bash scripts/install-deps.sh app
dotnet build src/SimulatorApp/SimulatorApp.vbproj -c Release -nologo -v quiet
exec mono src/SimulatorApp/bin/Release/net48/SimulatorApp.exe "$@"
