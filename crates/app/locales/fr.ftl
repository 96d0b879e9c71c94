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

