from yaseer.cli import main

raise SystemExit(main())
