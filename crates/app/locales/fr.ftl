### quarter-car

quarter-car-legend-comfort = confort { $low } et { $high }
quarter-car-legend-performance = sport { $low } et { $high }
quarter-car-legend-critical = critique { $zeta } (×)
quarter-car-legend-overdamped = suramorti { $zeta } (●)
quarter-car-group = { $group ->
        [comfort] confort
        [performance] sport
        [critical] critique
       *[overdamped] suramorti
    }
quarter-car-crossings = { $count ->
        [0] ne traverse pas l'équilibre
        [one] traverse l'équilibre une fois avant de se stabiliser
       *[other] traverse l'équilibre { $count } fois avant de se stabiliser
    }
quarter-car-crossings-inside-band = se stabilise avant de traverser l'équilibre (son rebond reste dans la bande)
quarter-car-settles-after = reste dans ±{ $band } de x₀ autour du repos après { $time }
quarter-car-does-not-settle = ne se stabilise pas
quarter-car-rebound = rebond maximal de { $rebound } à { $time }
quarter-car-no-rebound = aucun rebond
quarter-car-describe-design = Ce réglage (ζ = { $zeta }, { $regime }) : { $crossings }, { $settling }, { $rebound }.
quarter-car-describe-undamped = Ce réglage (ζ = 0, non amorti) : oscille indéfiniment entre ±{ $amplitude } à { $frequency }.
quarter-car-describe-unsettled = Ce réglage ({ $regime }) : ne se stabilise pas.
quarter-car-list-separator = {" ; "}
quarter-car-describe-response = { $design } Réglages de référence sur cette voiture, stabilisation dans ±{ $band } de x₀ : { $family }.
quarter-car-member-settles = { $group } ζ = { $zeta } en { $time }
quarter-car-member-unsettled = { $group } ζ = { $zeta } ne se stabilise pas
quarter-car-two-sentences = { $first } { $second }
quarter-car-settling-fastest = Temps d'établissement de la réponse libre dans ±{ $band } de x₀ en fonction de ζ pour cette voiture : le plus court à ζ = { $zeta } ({ $time }), juste après un saut ; il chute brusquement chaque fois qu'un rebond passe à l'intérieur de la bande.
quarter-car-settling-curve = Temps d'établissement de la réponse libre dans ±{ $band } de x₀ en fonction de ζ.
quarter-car-settling-design = Ce réglage, ζ = { $zeta }, se stabilise en { $time }.
quarter-car-settling-design-never = Ce réglage, ζ = { $zeta }, ne se stabilise jamais.
quarter-car-sensitivity-range = Avec une masse suspendue entre { $low } et { $high } (±{ $variation }) et les mêmes amortisseur et ressort, ζ varie de { $min } à { $max } (nominal { $nominal }) ; l'estimation linéaire va de { $linear_min } à { $linear_max }.
quarter-car-sensitivity-undefined = La plage du taux d'amortissement n'est pas définie pour ce réglage.
quarter-car-sensitivity-inside = Le ζ de stabilisation la plus rapide, { $zeta }, se trouve dans cette plage : les charges qui font passer ζ en dessous se stabilisent nettement plus tard.
quarter-car-sensitivity-outside = Le ζ de stabilisation la plus rapide, { $zeta }, se trouve hors de cette plage.
quarter-car-schematic = Quart de véhicule à t = { $time } : la caisse est à { $displacement } du repos ({ $side ->
        [above] au-dessus
       *[below] en dessous
    }), route fixe.
quarter-car-settling-title = Temps d'établissement dans ±{ $band } de x₀ en fonction de ζ
quarter-car-axis-zeta = taux d'amortissement ζ
quarter-car-axis-zeta-fastest = taux d'amortissement ζ (tirets : ζ le plus rapide = { $zeta })
quarter-car-axis-settling-time = temps d'établissement t_s
quarter-car-axis-sprung-mass = masse suspendue m
quarter-car-fastest = ζ le plus rapide = { $zeta }
quarter-car-this-design = ce réglage
quarter-car-nominal = nominale
quarter-car-road = route
quarter-car-band-label = ±{ $band } de x₀
quarter-car-series-design = ce réglage, ζ { $zeta }
quarter-car-title = Suspension quart de véhicule
quarter-car-summary = Un coin de voiture : la caisse (masse suspendue m) sur un ressort k et un amortisseur c au-dessus d'une route fixe, déplacée de x₀ puis lâchée sans vitesse (x′(0) = 0). c et ζ sont deux vues du même amortisseur, c = 2ζ√(km) : déplacez l'un, l'autre suit ; changer m ou k conserve l'amortisseur, donc ζ varie. Les courbes fines montrent les réglages classiques sur cette voiture : le réglage confort (ζ ≈ 0,3–0,4) rebondit, le réglage sport (ζ ≈ 0,65–0,7) se stabilise le plus vite, les réglages critique (ζ = 1) et suramorti reviennent sans rebond, mais plus lentement. Le temps d'établissement saute quand ζ franchit les valeurs où un rebond passe à l'intérieur de la bande : le ζ le plus rapide se trouve juste après un tel saut, si bien qu'une charge plus lourde peut faire basculer une voiture bien réglée (voir le graphique de la masse). La stabilisation est mesurée sur cette réponse libre : le temps d'établissement est le dernier instant où |x| vaut bande·|x₀|, après quoi la caisse reste dans ±bande·|x₀| autour du repos (et non dans la bande autour de la valeur finale d'une réponse indicielle).
quarter-car-param-m = masse suspendue
quarter-car-param-k = raideur du ressort
quarter-car-param-c = coefficient d'amortissement
quarter-car-param-zeta = taux d'amortissement
quarter-car-param-x0 = déplacement initial
quarter-car-param-band = bande de stabilisation autour du repos, relative à x₀
quarter-car-param-dm = variation de la masse suspendue
quarter-car-readout-regime = régime
quarter-car-readout-wn = pulsation propre ωₙ
quarter-car-readout-fn = fréquence propre fₙ
quarter-car-readout-zeta = taux d'amortissement ζ
quarter-car-readout-c = coefficient d'amortissement c utilisé
quarter-car-readout-c-crit = amortissement critique 2√(km)
quarter-car-readout-wd = pulsation amortie ω_d
quarter-car-readout-settling-time = temps d'établissement t_s dans ±bande·|x₀| (réponse libre)
quarter-car-readout-overshoot = rebond maximal (rapporté à x₀)
quarter-car-readout-peak-time = instant du rebond maximal
quarter-car-readout-zeta-argmin = ζ de stabilisation la plus rapide (réponse libre, même bande)
quarter-car-readout-settling-min = son temps d'établissement
quarter-car-readout-zeta-lo = ζ à masse +dm %
quarter-car-readout-zeta-hi = ζ à masse −dm %
quarter-car-plot-response = Déplacement de la caisse x(t)
quarter-car-plot-settling = Temps d'établissement de la réponse libre en fonction de ζ
quarter-car-plot-sensitivity = ζ quand la masse suspendue varie
quarter-car-preset-1 = Confort ζ = 0,3
quarter-car-preset-2 = Confort ζ = 0,4
quarter-car-preset-3 = Sport ζ = 0,65
quarter-car-preset-4 = Sport ζ = 0,7
quarter-car-preset-5 = Critique ζ = 1
quarter-car-preset-6 = Suramorti ζ = 2

### quarter-car-2dof

quarter-car-2dof-describe-motion = Sur { $road ->
        [bump] une bosse
        [step] une marche
        [sine] une route sinusoïdale
       *[random] une route aléatoire
    } (hauteur maximale de la route { $road_peak }), la caisse se déplace d'au plus { $body } (à { $body_time }) et la roue d'au plus { $wheel } (à { $wheel_time }).
quarter-car-2dof-describe-acceleration = L'accélération de la caisse culmine à { $peak } ({ $peak_g } g) ; sur le trajet depuis le repos, de 0 à { $window }, sa valeur efficace est de { $rms }.
quarter-car-2dof-describe-tyre-lift-off = La déflexion du pneu (roue au-dessus de la route, positive = pneu qui se décharge) varie de { $low } à { $high }, valeur efficace { $rms } ; elle atteint la déflexion statique { $limit } pour la première fois à { $time }, où la force du pneu tombe à zéro et la roue quitte la route : décollements { $lift_offs } ; temps hors de la route { $airborne }.
quarter-car-2dof-describe-tyre-contact = La déflexion du pneu (roue au-dessus de la route, positive = pneu qui se décharge) varie de { $low } à { $high }, valeur efficace { $rms } ; elle reste sous la déflexion statique { $limit }, donc le pneu garde le contact.
quarter-car-2dof-describe-frf = Réponse en fréquence par unité de hauteur de route, en axes logarithmiques. La caisse suit les ondulations lentes de la route (rapport 1), culmine à { $body_peak } près du pompage de la caisse à { $body_frequency }, et est isolée au-delà : { $at_20 } à 20 Hz. La déflexion du pneu culmine à { $tyre_peak } près du battement de roue à { $tyre_frequency }.
quarter-car-2dof-schematic = Quart de véhicule à t = { $time } : caisse { $body }, roue { $wheel }, route { $road } (dessinées à une échelle commune).
quarter-car-2dof-schematic-title = Schéma
quarter-car-2dof-axis-height = hauteur par rapport à l'équilibre
quarter-car-2dof-axis-acceleration = accélération z_s″
quarter-car-2dof-axis-tyre-deflection = déflexion du pneu z_u − u
quarter-car-2dof-axis-frequency = fréquence f
quarter-car-2dof-axis-magnitude = amplitude par unité de hauteur de route
quarter-car-2dof-series-road = route u
quarter-car-2dof-series-wheel = roue z_u
quarter-car-2dof-series-body = caisse z_s
quarter-car-2dof-series-body-acceleration = accélération de la caisse
quarter-car-2dof-series-rms = ± valeur efficace
quarter-car-2dof-series-lift-off = décollement (déflexion statique)
quarter-car-2dof-series-off-road = roue décollée
quarter-car-2dof-series-body-gain = caisse/route
quarter-car-2dof-series-tyre-gain = défl. pneu/route
quarter-car-2dof-marker-road = route
quarter-car-2dof-title = Quart de véhicule avec caisse et roue
quarter-car-2dof-summary = Deux masses, deux modes. La caisse (masse suspendue m_s) repose sur le ressort de suspension k_s et l'amortisseur c_s ; la roue (masse non suspendue m_u) repose sur le ressort du pneu k_t, qui suit la route u(t). Le pompage de la caisse, vers 1–1,5 Hz, est le mouvement de la caisse sur la suspension souple ; le battement de roue, vers 10–15 Hz, est la roue légère qui rebondit entre le pneu raide et la suspension. Les réponses en fréquence montrent les deux : la caisse suit les ondulations lentes de la route, passe par-dessus les rapides et vibre le plus près du pompage ; la déflexion du pneu, qui décide de l'adhérence, culmine au battement de roue. Le pneu ne peut que pousser : quand la roue remonte au-delà de sa déflexion statique, la force du pneu est nulle et la roue quitte la route jusqu'à ce qu'elle retombe. Le confort se juge à l'accélération efficace (RMS) de la caisse, la tenue de route à la déflexion efficace du pneu, toutes deux sur le trajet depuis le repos, 0 … T. La réponse est exacte entre les échantillons de la route, assez rapprochés pour suivre chaque bosse et chaque battement de roue. Les déplacements sont comptés depuis l'équilibre statique, positifs vers le haut ; la route aléatoire additionne 64 sinusoïdes selon le spectre ISO 8608 sur 0,5–20 Hz. Sur celle-ci, la page indique aussi l'accélération efficace stationnaire de la caisse sur la route ISO 8608 complète, non pondérée et pondérée par le filtre W_k de l'ISO 2631-1 (a_w, la mesure du confort), tirée de l'équation de Lyapunov de la voiture.
quarter-car-2dof-param-ms = masse de la caisse (suspendue)
quarter-car-2dof-param-mu = masse de la roue (non suspendue)
quarter-car-2dof-param-ks = raideur de la suspension
quarter-car-2dof-param-kt = raideur du pneu
quarter-car-2dof-param-cs = amortissement de la suspension
quarter-car-2dof-param-road = excitation de la route
quarter-car-2dof-param-road-bump = bosse unique (1 − cos)
quarter-car-2dof-param-road-step = marche (bordure de trottoir)
quarter-car-2dof-param-road-sine = sinusoïde
quarter-car-2dof-param-road-random = route aléatoire (ISO 8608)
quarter-car-2dof-param-h = hauteur de la bosse ou de la marche, amplitude du sinus
quarter-car-2dof-param-L = longueur de la bosse
quarter-car-2dof-param-V = vitesse
quarter-car-2dof-param-f-road = fréquence de la route sinusoïdale
quarter-car-2dof-param-class = classe de la route aléatoire
quarter-car-2dof-param-class-A = A (très bonne)
quarter-car-2dof-param-class-B = B (bonne)
quarter-car-2dof-param-class-C = C (moyenne)
quarter-car-2dof-param-class-D = D (mauvaise)
quarter-car-2dof-param-class-E = E (très mauvaise)
quarter-car-2dof-param-class-F = F
quarter-car-2dof-param-class-G = G
quarter-car-2dof-param-class-H = H
quarter-car-2dof-param-seed = graine de la route aléatoire
quarter-car-2dof-readout-f-body = fréquence de pompage de la caisse [Hz]
quarter-car-2dof-readout-f-wheel = fréquence de battement de roue [Hz]
quarter-car-2dof-readout-window = fenêtre de la valeur efficace : le trajet depuis le repos, 0 … T
quarter-car-2dof-readout-rms-body-accel = accélération efficace de la caisse sur 0 … T (confort)
quarter-car-2dof-readout-rms-tyre-deflection = déflexion efficace du pneu z_u − u sur 0 … T (tenue de route)
quarter-car-2dof-readout-max-travel = plus grand débattement de suspension |z_s − z_u|
quarter-car-2dof-readout-static-tyre-deflection = déflexion statique du pneu (la roue décolle au-delà)
quarter-car-2dof-readout-lift-off = premier décollement : la force du pneu atteint zéro
quarter-car-2dof-readout-airborne-time = durée pendant laquelle la roue a quitté la route
quarter-car-2dof-readout-rms-road = hauteur efficace de la route (route aléatoire)
quarter-car-2dof-readout-stationary-accel = accélération efficace stationnaire de la caisse, route ISO 8608 complète (route aléatoire)
quarter-car-2dof-readout-stationary-weighted-accel = a_w stationnaire : accélération efficace de la caisse pondérée par W_k de l'ISO 2631-1 (route aléatoire)
quarter-car-2dof-readout-body-gain = amplitude caisse / route à la fréquence du sinus
quarter-car-2dof-readout-tyre-gain = déflexion du pneu / amplitude de la route à la fréquence du sinus
quarter-car-2dof-plot-motion = Caisse, roue et route
quarter-car-2dof-plot-accel = Accélération de la caisse
quarter-car-2dof-plot-frf = Réponse en fréquence par unité de hauteur de route
quarter-car-2dof-plot-tyre = Déflexion du pneu
quarter-car-2dof-preset-1 = Ralentisseur de 5 cm à 10 m/s
quarter-car-2dof-preset-2 = Bordure de trottoir de 5 cm
quarter-car-2dof-preset-3 = Ondulation au pompage de la caisse
quarter-car-2dof-preset-4 = Ondulation au battement de roue
quarter-car-2dof-preset-5 = Route aléatoire, classe C, 20 m/s
quarter-car-2dof-preset-6 = Amortisseur souple sur route dégradée

